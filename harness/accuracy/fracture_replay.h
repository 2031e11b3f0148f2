#pragma once
/// A fracturer's output against the exact reference's replay of the cuts it reports
/// (Fracturer::cut_plan): plane-slice's cut schedule, voronoi's bisector cells, fem-lite's crack planes,
/// or whatever plan a fracturer registered from outside the library states.

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <vector>

namespace shatter {

/// The exact replay of what `fracturer` does to `solid` with `params`: its cut plan replayed by
/// `replayer` (an exact reference that offers cut_plan_replay: plan_replayer, capable_fracturer.h).
/// Error for a fracturer that states no cut plan (naming it).
Result<std::vector<Fragment>> exact_replay(const Fracturer& fracturer, const CutPlanReplay& replayer, const Mesh& solid,
                                           const FractureParams& params);

/// How far fragments are from their exact replay.
struct ReplayMismatch {
  /// Largest |V_fast - V_exact| / V_exact over the fragments paired by nearest centroid (each exact
  /// fragment used once); dimensionless.
  double max_relative_volume = 0.0;
  /// Volume of the fragments left unpaired (either side) over the exact total; 0 when the counts agree.
  double unpaired_volume = 0.0;
  int fast_count = 0;   ///< fragments of the fracturer
  int exact_count = 0;  ///< fragments of the replay
};

/// Pairs `fast` with `exact` greedily by nearest centroid (in `fast` order) and measures the mismatch.
ReplayMismatch replay_mismatch(const std::vector<Fragment>& fast, const std::vector<Fragment>& exact);

}  // namespace shatter
