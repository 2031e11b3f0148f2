#pragma once
/// One destruction run of a case, frame by frame as a game runs it (DESIGN.md section 3): the offline
/// setup (pre-fracture, bonds, the first stress solve, colliders), then `frames` frames of 1/60 s, each
/// running the scheduled steps of the runtime event and one physics step. Every stage is timed.
///
/// The run is built from four parts (docs/pipeline.md section 7 names the files): the offline setup
/// (setup/: shared with `stress` and the accuracy runs through setup/offline_structure.h), the runtime
/// event as a sequence of phases (event/), one function per schedule mode (schedule/) and the frame
/// loop (frame/); run_state.h is what they share.
///
/// Design notes (the decisions DESIGN.md leaves open; docs/pipeline.md has the long form):
/// - The standing structure is what is still held: the fragments of components with an anchor. They
///   are static bodies (they do not move until something breaks them loose), so an impact is tested
///   against their meshes as they were fractured. Fragments that fell or flew are never hit again.
/// - The runtime event: the impact fractures each standing fragment it reaches (fragments_near_impact)
///   with the runtime fracturer; the pieces are free debris, not bonded (a game's debris). The bonds of
///   every hit fragment are removed (bond update), the stress model breaks what then fails, and every
///   standing component left without an anchor falls as one compound body.
/// - The impulse is shared by the new pieces in proportion to their mass (each gets the same velocity
///   change, impulse / total mass, along the impact direction, at its own centroid): the total momentum
///   given is the impulse, and no piece is spun by an arbitrary lever arm.
/// - Frame time = the wall time of everything that runs in the frame. Setup is timed per stage but is
///   not a frame: a game does it while loading.
/// - Skips (StageLog): the case's `needs` (and what they imply: physics needs colliders); the cache;
///   the impact's radius (fragments rejected by box before their surface is measured); no gravity or
///   no anchors for a load-driven stress model; a bond break re-solves only its component. With
///   `no_skip` every automatic skip is off (the needs still hold): the pre-fracture is recomputed,
///   every standing fragment's surface is measured, every component is re-solved each round and the
///   stress solve runs even without gravity or anchors. Fragments, bonds and falling clusters are the
///   same either way (tests/harness/pipeline/destruction_run_tests.cpp).

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/registry/registries.h"
#include "algorithms/stress/stress_model.h"
#include "harness/cases/case.h"
#include "harness/cases/load_solid.h"
#include "harness/cases/run_settings.h"
#include "harness/metrics/fracture_metrics.h"
#include "harness/pipeline/prefracture_cache.h"
#include "harness/pipeline/stage.h"
#include "harness/results/frame_stage_times.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shatter {

class FrameRecorder;

/// A case with its solid built and validated once, for many runs.
struct PreparedCase {
  Case spec;     ///< the case as loaded
  Solid solid;   ///< its validated solid
};

/// Builds and validates `c`'s solid. Errors name the case and the mesh key.
Result<PreparedCase> prepare_case(Case c);

/// What one run does; empty names and zero counts take the case's values (run_settings).
struct RunOptions {
  int prefracture_fragments = 0;      ///< pre-fracture count (0: the case's; unused for explicit planes)
  int runtime_fragments = 0;          ///< pieces per hit fragment (0: the case's runtime.fragments)
  std::string prefracture_fracturer;  ///< pre-fracture algorithm (empty: the case's)
  std::string runtime_fracturer;      ///< runtime algorithm (empty: the case's)
  std::string stress_model;           ///< stress model (empty: the case's)
  std::uint64_t repetition = 0;       ///< added to the case's seed: each repetition fractures anew
  int frames = 0;                     ///< frames to run (0: the case's); an impact after the last frame lands in it
  bool no_skip = false;               ///< turn every automatic skip off (see the file comment)
  const PrefractureCache* cache = nullptr;  ///< pre-fracture cache, or none
  /// Clean self-intersection verdicts shared with other runs (a grid passes one to all its cells), or
  /// none. Changes no result, only which input checks run again.
  SelfIntersectionVerdicts* verdicts = nullptr;
  int partition_samples = 256;        ///< points of the partition-error test (untimed; 0 skips it)
  std::optional<ScheduleMode> schedule;  ///< schedule mode (none: the case's schedule.mode)
  /// Threads of a runtime event's independent work (1..kMaxWorkerThreads, workers.h): the hit
  /// fragments' fractures and the pieces' hulls run on this many at once (under `amortized` a step
  /// takes one hit fragment, or kColliderBatch pieces, per thread; under the other schedules, whose
  /// steps all run in one frame, one step takes them all). Changes no result, only which frames are
  /// how long and how many steps the event takes.
  int threads = 1;
  /// Records every body in every frame for playback (frame/frame_recorder.h), or none. Its work runs
  /// between frames, outside their time; while it records, the run also notes what each body is made
  /// of where the body is made (a few bytes per body, inside the colliders stage).
  FrameRecorder* recorder = nullptr;
};

/// When one runtime event started and when its result took part in the world (docs/pipeline.md
/// section 6). Frames are indices into RunResult::frame_ms.
struct EventLatency {
  int trigger_frame = -1;   ///< the frame the event's work may start in (prefetch: prefetch_frames before the impact)
  int impact_frame = -1;    ///< the frame the impact lands in
  int visible_frame = -1;   ///< the frame whose physics step first has the new bodies (-1: the impact fractured nothing)
  int frames = 0;           ///< visible_frame - trigger_frame + 1: frames from trigger to visible, both counted (0 when not visible)
  int after_impact = 0;     ///< visible_frame - impact_frame: frames the result lags the impact
  double ms = 0.0;          ///< trigger to visible at 60 Hz: each frame counted max(its wall time, 1/60 s), ms
};

/// Error figures of the runtime fracture, over every hit fragment and its pieces.
struct RuntimeFractureError {
  int hit_count = 0;                  ///< fragments fractured at runtime
  int pieces = 0;                     ///< fragments they became
  double volume_error = 0.0;          ///< largest |sum of piece volumes - hit volume| / hit volume
  double partition_error = 0.0;       ///< largest partition error of one hit fragment's pieces
  bool all_closed = true;             ///< every piece closed and oriented
  double min_fragment_volume = 0.0;   ///< smallest piece, m^3 (0 without pieces)
};

/// Everything one run measured and produced.
struct RunResult {
  std::uint64_t prefracture_seed = 0;       ///< seed of the pre-fracture
  std::uint64_t runtime_seed = 0;           ///< seed of the runtime fracture (per hit: + hit index)
  std::vector<double> frame_ms;             ///< wall time of each frame
  std::vector<int> event_frames;            ///< frames in which an impact landed, ascending
  double event_ms = 0.0;                    ///< time of the first event frame (0 without impacts)
  std::vector<double> frame_cpu_ms;         ///< thread CPU time of each frame
  StageClocks setup;                        ///< offline stage times (before frame 0), wall and CPU
  StageClocks frame_stages;                 ///< stage times inside frames, summed over the frames
  /// Wall time of each stage in each frame, ms, rounded to the clock's 1 ns: each stage's frames add up
  /// to its frame_stages.wall, and a frame's stages to at most its frame_ms.
  FrameStageTimes frame_stage_ms;
  StageLog stages;                          ///< what ran and what was skipped, and why
  bool cache_hit = false;                   ///< the pre-fracture came from the cache

  std::vector<Fragment> fragments;          ///< the pre-fracture
  SupportGraph graph;                       ///< its bonds (empty when bonds are not needed)
  std::vector<std::uint8_t> broken;         ///< per bond: 1 when broken by the end of the run
  std::vector<int> hit;                     ///< pre-fracture fragments fractured at runtime, in event order
  std::vector<std::vector<Fragment>> pieces;///< per hit fragment, its runtime pieces
  std::vector<std::vector<int>> falling_clusters;  ///< fragment indices of each cluster that fell, in order
  int bodies = 0;                           ///< bodies in the physics world at the end
  int stress_rounds = 0;                    ///< rounds of breaking, summed over the stress solves
  SolverReport solver;                      ///< summed over the stress solves

  ScheduleMode schedule = ScheduleMode::immediate;  ///< the schedule the run used
  std::vector<EventLatency> latencies;      ///< per event, in the order the impacts land
  EventLatency latency;                     ///< the event with the largest `ms` (all -1/0 without one)
  std::vector<double> step_ms;              ///< wall time of every event step, in order (docs/pipeline.md section 6)
  double largest_step_ms = 0.0;             ///< the largest of step_ms
  std::vector<double> frame_work_ms;        ///< per frame: wall time of the event steps run in it
  std::vector<int> frame_bodies;            ///< per frame: bodies in the physics world at its end
  std::vector<int> frame_particles;         ///< per frame: debris particles alive at its end
  int bodies_peak = 0;                      ///< largest of frame_bodies
  int faded = 0;                            ///< runtime pieces removed by the fade-out
  int particles_spawned = 0;                ///< debris particles spawned
  int particles_peak = 0;                   ///< largest of frame_particles

  FractureMetrics prefracture_error;        ///< error figures of the pre-fracture (untimed)
  RuntimeFractureError runtime_error;       ///< error figures of the runtime fracture (untimed)
};

/// The settings of one run of `c` with `options` (resolve_settings).
RunSettings run_settings(const Case& c, const RunOptions& options);

/// Runs `prepared` once with `options`. Errors (unknown algorithm names with the case key or option,
/// an anchor region touching no fragment, a failed fracture or solve) name what failed.
/// Its fracturers and stress model are created from `registries` (with the case's settings for the
/// case's own plugins).
Result<RunResult> run_destruction(const PreparedCase& prepared, const RunOptions& options,
                                  const Registries& registries);

}  // namespace shatter
