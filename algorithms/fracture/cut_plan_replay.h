#pragma once
/// A fracturer's capability to replay another fracturer's cut plan (Fracturer::cut_plan): asked for
/// through Fracturer::cut_plan_replay(). The accuracy command replays each fracturer's plan with the
/// exact reference that offers it (Fracturer::exact_reference), chosen by the capability, never by name.

#include "algorithms/core/fragment.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/cut_plan.h"

#include <vector>

namespace shatter {

/// Replaying a cut plan.
class CutPlanReplay {
 public:
  virtual ~CutPlanReplay() = default;
  /// The fragments of `solid` (a validated closed mesh) cut as `plan` says: a recursive schedule, the
  /// planes in order, or the cells (cut_plan.h). Errors for a plan it cannot replay (its size, a bad plane).
  [[nodiscard]] virtual Result<std::vector<Fragment>> replay(const Mesh& solid, const CutPlan& plan) const = 0;
};

}  // namespace shatter
