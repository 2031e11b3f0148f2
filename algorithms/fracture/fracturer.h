#pragma once
/// The fracturer interface: every fracture algorithm turns one closed solid into closed fragments.
///
/// Contract (checked by the conformance test for every registered fracturer): the input is a solid
/// that passed validate_solid; every output fragment is closed, consistently outward-oriented, with
/// faces tagged surface or cut; the fragments partition the input (volumes sum to the input volume);
/// the same input, parameters and seed give the same fragments in the same order.

#include "algorithms/core/fragment.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/cut_plan.h"
#include "algorithms/fracture/cut_plan_replay.h"
#include "algorithms/fracture/plane_cutting.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace shatter {

class SelfIntersectionVerdicts;

/// Where and how hard a fragment is hit.
struct Impact {
  Vec3 point = Vec3::Zero();           ///< m, world
  Vec3 direction = -Vec3::UnitZ();     ///< unit direction of the impulse
  double impulse = 0.0;                ///< N s
  double radius = 0.0;                 ///< m; 0 = the whole piece is affected
};

/// What a fracturer is asked for.
struct FractureParams {
  int fragments = 10;                  ///< requested number of fragments (>= 1)
  std::uint64_t seed = 1;              ///< random seed; same seed, same output
  std::optional<Impact> impact;        ///< where the piece is hit, when it is
  /// Clean self-intersection verdicts the caller keeps between fractures (self_intersection_verdicts.h),
  /// or none: every input check then runs. Changes no output, only what is tested again.
  SelfIntersectionVerdicts* verdicts = nullptr;
};

/// A fracture algorithm. Implementations are stateless after construction and thread-compatible.
class Fracturer {
 public:
  virtual ~Fracturer() = default;
  /// Registered name, for example "plane-slice".
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// Fractures `solid` (a validated closed mesh). Errors only for parameters it cannot honour.
  [[nodiscard]] virtual Result<std::vector<Fragment>> fracture(const Mesh& solid,
                                                               const FractureParams& params) const = 0;
  /// The cuts `fracture(solid, params)` makes, for the exact replay; none (the default) when the
  /// fracturer cannot state them. Errors as fracture() does.
  [[nodiscard]] virtual Result<std::optional<CutPlan>> cut_plan(const Mesh& solid,
                                                                const FractureParams& params) const {
    (void)solid;
    (void)params;
    return std::optional<CutPlan>();
  }
  /// The capability to cut by planes the caller chooses (plane_cutting.h), or null (the default) when
  /// the fracturer only cuts where it chooses. The object lives as long as the fracturer.
  [[nodiscard]] virtual const PlaneCutting* plane_cutting() const { return nullptr; }
  /// The capability to replay another fracturer's cut plan (cut_plan_replay.h), or null (the default).
  /// The object lives as long as the fracturer.
  [[nodiscard]] virtual const CutPlanReplay* cut_plan_replay() const { return nullptr; }
  /// True for an exact reference: the fracturer others are replayed with (through its cut_plan_replay),
  /// not itself measured.
  [[nodiscard]] virtual bool exact_reference() const { return false; }
  /// The relative volume error |sum of the fragments' volumes - the input's| / the input's that this
  /// fracturer's fragments may carry by design: 0 (the default) for cuts that keep the volume to
  /// round-off; an approximate method (a level set on a voxel grid) states its own. The host's output
  /// check accepts up to it (fracture_output_check.h: at most kMaxStatedVolumeTolerance).
  [[nodiscard]] virtual double volume_tolerance() const { return 0.0; }
};

}  // namespace shatter
