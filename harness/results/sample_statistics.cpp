#include "harness/results/sample_statistics.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace shatter {

double quantile_of_sorted(std::span<const double> sorted, double p) {
  assert(p >= 0.0 && p <= 1.0);
  assert(std::is_sorted(sorted.begin(), sorted.end()));
  if (sorted.empty()) return 0.0;
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  const double t = h - static_cast<double>(lo);
  // Written as a weighted sum so that equal neighbours give exactly their value.
  return (1.0 - t) * sorted[lo] + t * sorted[lo + 1];
}

SampleStatistics sample_statistics(std::span<const double> samples) {
  SampleStatistics s;
  if (samples.empty()) return s;
  assert(std::all_of(samples.begin(), samples.end(), [](double x) { return std::isfinite(x); }));
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  // Summing in ascending order loses less to rounding for the positive values timings are.
  double sum = 0.0;
  for (double x : sorted) sum += x;
  s.count = sorted.size();
  s.mean = sum / static_cast<double>(s.count);
  s.median = quantile_of_sorted(sorted, 0.5);
  s.p95 = quantile_of_sorted(sorted, 0.95);
  s.p99 = quantile_of_sorted(sorted, 0.99);
  s.min = sorted.front();
  s.max = sorted.back();
  return s;
}

double median_of(std::span<const double> samples) {
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  return quantile_of_sorted(sorted, 0.5);
}

}  // namespace shatter
