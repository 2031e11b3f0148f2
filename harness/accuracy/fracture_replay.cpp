#include "harness/accuracy/fracture_replay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace shatter {

Result<std::vector<Fragment>> exact_replay(const Fracturer& fracturer, const CutPlanReplay& replayer, const Mesh& solid,
                                           const FractureParams& params) {
  Result<std::optional<CutPlan>> plan = fracturer.cut_plan(solid, params);
  if (!plan) return plan.error();
  if (!plan->has_value()) return Error{"no exact replay for fracturer '" + std::string(fracturer.name()) + "'"};
  return replayer.replay(solid, **plan);
}

ReplayMismatch replay_mismatch(const std::vector<Fragment>& fast, const std::vector<Fragment>& exact) {
  ReplayMismatch m;
  m.fast_count = static_cast<int>(fast.size());
  m.exact_count = static_cast<int>(exact.size());
  double exact_total = 0.0;
  for (const Fragment& e : exact) exact_total += e.mass.volume;
  std::vector<bool> used(exact.size(), false);
  double unpaired = 0.0;
  for (const Fragment& f : fast) {
    std::size_t best = exact.size();
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const double d = (f.mass.centroid - exact[k].mass.centroid).norm();
      if (!used[k] && d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
    if (best == exact.size()) {
      unpaired += std::abs(f.mass.volume);
      continue;
    }
    used[best] = true;
    const double v = exact[best].mass.volume;
    const double relative = v > 0.0 ? std::abs(f.mass.volume - v) / v : std::numeric_limits<double>::infinity();
    m.max_relative_volume = std::max(m.max_relative_volume, relative);
  }
  for (std::size_t k = 0; k < exact.size(); ++k)
    if (!used[k]) unpaired += exact[k].mass.volume;
  m.unpaired_volume = exact_total > 0.0 ? unpaired / exact_total : 0.0;
  return m;
}

}  // namespace shatter
