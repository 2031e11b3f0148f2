#pragma once
/// What one destruction run keeps from its setup to its last frame, shared by the pipeline's parts:
/// the offline setup (setup/), the runtime event's phases (event/), the schedules (schedule/) and the
/// frame loop (frame/).
///
/// Design note: one plain struct, not a class with private members, because each part is a free
/// function over it; the run's outputs live in `result` from the start, so nothing is copied at the
/// end. The case, the solid and the options are borrowed from the caller of run_destruction.

#include "algorithms/core/self_intersection_verdicts.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/stress/stress_model.h"
#include "harness/pipeline/debris_field.h"
#include "harness/pipeline/destruction_run.h"
#include "harness/pipeline/physics/physics_world.h"
#include "harness/pipeline/stage_plan.h"
#include "harness/pipeline/workers.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace shatter {

/// A runtime piece that shrinks and then leaves the physics world (case key fade_out).
struct FadingPiece {
  int body = -1;           ///< its body in the physics world
  int visible_frame = 0;   ///< the frame it entered the world
};

/// The state of one destruction run.
struct RunState {
  /// A run of `prepared` with `options` and the plugins of `plugins`; all must outlive the state.
  RunState(const PreparedCase& prepared, const RunOptions& run_options, const Registries& plugins)
      : spec(prepared.spec),
        solid(prepared.solid),
        options(run_options),
        settings(run_settings(prepared.spec, run_options)),
        registries(plugins),
        workers(run_options.threads) {}

  const Case& spec;            ///< the case
  const Solid& solid;          ///< its validated solid
  const RunOptions& options;   ///< what this run overrides
  const RunSettings settings;  ///< the options over the case's values (run_settings)
  const Registries& registries;  ///< where the run's fracturers and stress model come from
  StagePlan plan;              ///< the stages the case's needs imply
  RunResult result;            ///< everything measured and produced so far

  std::unique_ptr<Fracturer> prefracturer;       ///< pre-fracture algorithm (for explicit planes: their plane_cutter)
  std::unique_ptr<Fracturer> runtime_fracturer;  ///< runtime algorithm
  std::unique_ptr<StressModel> stress_model;     ///< stress model
  /// The stress model's solver of result.graph, made at the first solve and kept for the run (every
  /// event's cascade reuses what it keeps: factors, a windowed model's structure at rest); a solver
  /// gives what a new one would, bit for bit (stress_model.h).
  std::unique_ptr<StressSolver> stress_solver;
  int runtime_fragments = 0;                     ///< pieces requested per hit fragment
  Loads loads;                                   ///< gravity of the case

  /// The fragments the case's impacts reach, checked at setup as the runtime fracturer's inputs
  /// (check_solid), so that the event's fractures find their verdicts; none under --no-skip.
  std::unique_ptr<SelfIntersectionVerdicts> checked_inputs;
  std::vector<std::uint8_t> standing;   ///< per fragment: 1 while part of the held structure
  std::vector<std::uint8_t> anchored;   ///< per fragment: 1 when it overlaps an anchor region
  std::vector<int> static_body;         ///< per fragment: its static body in the world, or -1
  Workers workers;                      ///< the threads of the event's fractures and colliders and of
                                        ///< the steps' narrow phase (before the world: outlives it)
  std::unique_ptr<PhysicsWorld> world;  ///< the physics world (none when colliders are not needed)

  int frame = 0;                        ///< the frame being run (setup: 0)
  std::vector<FadingPiece> fading;      ///< runtime pieces fading out, in the order they entered
  std::unique_ptr<DebrisField> debris;  ///< the particles (case key debris), or none
};

}  // namespace shatter
