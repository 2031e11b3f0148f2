#pragma once
/// Summary figures of a set of timing samples (DESIGN.md sections 6 and 8: `frame_ms` holds `mean`,
/// `median`, `p95`, `p99`, `max` and `min`).
///
/// Percentiles interpolate linearly between order statistics: with the n samples sorted ascending as
/// x[0] <= ... <= x[n-1], the p-quantile (0 <= p <= 1) is at the fractional index h = (n - 1) p, and
/// its value is x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]). This is Hyndman and Fan's
/// "type 7", the default of NumPy's `percentile`, R's `quantile` and Excel's `PERCENTILE.INC`; it gives
/// the minimum at p = 0, the maximum at p = 1, and the usual median.

#include <cstddef>
#include <span>

namespace shatter {

/// Summary of a set of samples; every figure is in the samples' unit (ms for timings).
struct SampleStatistics {
  double mean = 0.0;    ///< arithmetic mean
  double median = 0.0;  ///< 0.5-quantile (type 7, see the file comment)
  double p95 = 0.0;     ///< 0.95-quantile (type 7)
  double p99 = 0.0;     ///< 0.99-quantile (type 7)
  double max = 0.0;     ///< largest sample
  double min = 0.0;     ///< smallest sample
  std::size_t count = 0;  ///< number of samples
};

/// Statistics of `samples` (any order, every value finite). No samples give all figures 0 and count 0.
SampleStatistics sample_statistics(std::span<const double> samples);

/// The p-quantile (0 <= p <= 1, type 7) of samples already sorted ascending; 0 when there are none.
double quantile_of_sorted(std::span<const double> sorted, double p);

/// The median of `samples` (any order, every value finite); 0 when there are none.
double median_of(std::span<const double> samples);

}  // namespace shatter
