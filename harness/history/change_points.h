#pragma once
/// Change points of a benchmark series: where its level steps. The method is E-divisive means
/// (Matteson and James 2014) as Apache Otava runs it (Fleming et al. 2023, "Hunter"):
///
/// 1. Split. Windows of `window` points, each starting half a window after the previous one (or at
///    the last change point the previous window found, when that is later). In each window the
///    divisive search repeats: of the segments the change points found so far leave, take the split
///    (tau, kappa) that maximises the E-statistic Q between [start, tau) and [tau, kappa) (alpha = 1),
///    and keep tau when a two-sided Student's t-test (pooled variance) between the values on either
///    side of it within its segment gives p <= a first-pass threshold (10 x max_pvalue below 0.05,
///    2 x below 0.5); the first candidate that fails ends the window. The union over the windows are
///    the weak change points.
/// 2. Merge. Each weak point's statistics are taken between its neighbours over the whole series;
///    then, repeatedly, the point of the largest p-value is dropped while that p-value is at least
///    max_pvalue, and after that the point of the smallest relative change while that change is at
///    most min_magnitude; the two neighbours of a dropped point are measured again.
///
/// A change point is the index of the first value of the new level.

#include <cstddef>
#include <span>
#include <vector>

namespace shatter {

/// The parameters of find_change_points, with their defaults (Otava's command line's).
struct ChangePointSettings {
  int window = 30;             ///< points per window of the split pass (at least 2)
  double max_pvalue = 0.001;   ///< largest p-value of the t-test a change point may have
  double min_magnitude = 0.0;  ///< smallest relative change of the means a change point must have
};

/// One change point and the two segments either side of it (up to the neighbouring change points).
struct SeriesChangePoint {
  std::size_t index = 0;      ///< first value of the new level
  double mean_before = 0.0;
  double mean_after = 0.0;
  double stddev_before = 0.0;  ///< population standard deviation of the segment before
  double stddev_after = 0.0;
  double pvalue = 1.0;         ///< two-sided Student's t-test between the segments
  /// max(|after / before - 1|, |before / after - 1|), a mean of 0 giving 0 for its term.
  [[nodiscard]] double magnitude() const;
};

/// The change points of `series` (in index order).
std::vector<SeriesChangePoint> find_change_points(std::span<const double> series, const ChangePointSettings& settings);

}  // namespace shatter
