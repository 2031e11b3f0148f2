#include "harness/history/change_points.h"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shatter {
namespace {

/// The statistics of the split of [lo, hi) at `index`.
SeriesChangePoint measure(std::span<const double> z, std::size_t lo, std::size_t index, std::size_t hi) {
  SeriesChangePoint cp;
  cp.index = index;
  const auto mean_std = [&](std::size_t a, std::size_t b, double& mean, double& stddev) {
    double sum = 0.0;
    for (std::size_t i = a; i < b; ++i) sum += z[i];
    mean = sum / static_cast<double>(b - a);
    double squares = 0.0;
    for (std::size_t i = a; i < b; ++i) squares += (z[i] - mean) * (z[i] - mean);
    stddev = b - a >= 2 ? std::sqrt(squares / static_cast<double>(b - a)) : 0.0;
  };
  mean_std(lo, index, cp.mean_before, cp.stddev_before);
  mean_std(index, hi, cp.mean_after, cp.stddev_after);
  const auto n1 = static_cast<double>(index - lo);
  const auto n2 = static_cast<double>(hi - index);
  const double df = n1 + n2 - 2.0;
  if (df <= 0.0) return cp;  // p = 1: two points say nothing of how different is significant
  // Pooled variance from the population deviations, as the two-sample test from summary statistics
  // is given them.
  const double pooled = ((n1 - 1.0) * cp.stddev_before * cp.stddev_before + (n2 - 1.0) * cp.stddev_after * cp.stddev_after) / df;
  const double spread = std::sqrt(pooled * (1.0 / n1 + 1.0 / n2));
  const double difference = cp.mean_before - cp.mean_after;
  if (spread == 0.0) {
    cp.pvalue = difference == 0.0 ? 1.0 : 0.0;
    return cp;
  }
  const double t = std::abs(difference / spread);
  if (!std::isfinite(t)) return cp;  // values beyond what the statistics can hold: no evidence either way (p = 1)
  const boost::math::students_t student(df);
  cp.pvalue = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(student, t)));
  return cp;
}

/// The best split of [lo, hi) (hi - lo > 1): the tau of the largest E-statistic Q(tau, kappa) over
/// lo < tau < kappa <= hi, scanned tau-major as a (hi - lo - 1)-square table whose entries below the
/// diagonal are 0 (the first largest wins).
std::pair<std::size_t, double> best_split(std::span<const double> z, std::size_t lo, std::size_t hi) {
  const std::size_t size = hi - lo - 1;
  double best = -std::numeric_limits<double>::infinity();
  std::size_t best_tau = lo + 1;
  for (std::size_t row = 0; row < size; ++row) {
    const std::size_t tau = lo + 1 + row;
    const double n = static_cast<double>(tau - lo);
    double within_x = 0.0;
    for (std::size_t i = lo; i < tau; ++i)
      for (std::size_t k = i + 1; k < tau; ++k) within_x += std::abs(z[i] - z[k]);
    double cross = 0.0;
    double within_y = 0.0;
    for (std::size_t col = 0; col < size; ++col) {
      const std::size_t kappa = lo + 2 + col;
      double q = 0.0;
      if (kappa > tau) {
        const std::size_t added = kappa - 1;  // the point that joins Y = [tau, kappa)
        for (std::size_t i = lo; i < tau; ++i) cross += std::abs(z[i] - z[added]);
        for (std::size_t j = tau; j < added; ++j) within_y += std::abs(z[j] - z[added]);
        const double m = static_cast<double>(kappa - tau);
        q = 2.0 / (m + n) * cross;
        if (n > 1.0) q -= 2.0 * m / ((m + n) * (n - 1.0)) * within_x;
        if (m > 1.0) q -= 2.0 * n / ((m + n) * (m - 1.0)) * within_y;
      }
      if (q > best) {
        best = q;
        best_tau = tau;
      }
    }
  }
  return {best_tau, best};
}

/// The segment bounds the sorted change points `cps` leave in [0, n), as (lo, hi) of the one holding `index`.
std::pair<std::size_t, std::size_t> segment_of(const std::vector<SeriesChangePoint>& cps, std::size_t index, std::size_t n) {
  std::size_t lo = 0;
  std::size_t hi = n;
  for (const SeriesChangePoint& cp : cps) {
    if (cp.index < index) lo = std::max(lo, cp.index);
    if (cp.index > index) hi = std::min(hi, cp.index);
  }
  return {lo, hi};
}

/// The divisive search on z[start, end) with the first-pass threshold; indices of the whole series.
std::vector<SeriesChangePoint> search_window(std::span<const double> series, std::size_t start, std::size_t end,
                                             double threshold) {
  const std::span<const double> z = series.subspan(start, end - start);
  std::vector<SeriesChangePoint> found;
  while (true) {
    // The segments the points found so far leave; the best split of each of more than one point.
    std::vector<std::size_t> bounds = {0};
    for (const SeriesChangePoint& cp : found) bounds.push_back(cp.index);
    bounds.push_back(z.size());
    bool any = false;
    double best_q = 0.0;
    std::size_t best_tau = 0;
    std::size_t best_lo = 0;
    std::size_t best_hi = 0;
    for (std::size_t s = 0; s + 1 < bounds.size(); ++s) {
      if (bounds[s + 1] - bounds[s] < 2) continue;
      const auto [tau, q] = best_split(z, bounds[s], bounds[s + 1]);
      if (!any || q > best_q) {
        any = true;
        best_q = q;
        best_tau = tau;
        best_lo = bounds[s];
        best_hi = bounds[s + 1];
      }
    }
    if (!any) break;
    const SeriesChangePoint cp = measure(z, best_lo, best_tau, best_hi);
    if (!(cp.pvalue <= threshold)) break;
    found.push_back(cp);
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  }
  for (SeriesChangePoint& cp : found) cp.index += start;
  return found;
}

}  // namespace

double SeriesChangePoint::magnitude() const {
  const double forward = mean_before == 0.0 ? 0.0 : mean_after / mean_before - 1.0;
  const double backward = mean_after == 0.0 ? 0.0 : mean_before / mean_after - 1.0;
  return std::max(std::abs(forward), std::abs(backward));
}

std::vector<SeriesChangePoint> find_change_points(std::span<const double> series, const ChangePointSettings& settings) {
  const std::size_t n = series.size();
  const auto window = static_cast<std::size_t>(std::max(settings.window, 2));
  const double p = settings.max_pvalue;
  const double first_pass = p < 0.05 ? 10.0 * p : (p < 0.5 ? 2.0 * p : p);

  // Split: the weak change points, the union over the windows.
  std::vector<SeriesChangePoint> weak;
  const std::size_t step = window / 2;
  std::size_t start = 0;
  while (start < n) {
    const std::size_t end = std::min(start + window, n);
    const std::vector<SeriesChangePoint> found = search_window(series, start, end, first_pass);
    const std::size_t last = found.empty() ? 0 : found.back().index;
    start = std::max(last, start + step);
    for (const SeriesChangePoint& cp : found)
      if (std::none_of(weak.begin(), weak.end(), [&](const auto& w) { return w.index == cp.index; })) weak.push_back(cp);
  }
  std::sort(weak.begin(), weak.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  const auto remeasure = [&](std::vector<SeriesChangePoint>& cps, std::size_t k) {
    const auto [lo, hi] = segment_of(cps, cps[k].index, n);
    cps[k] = measure(series, lo, cps[k].index, hi);
  };
  for (std::size_t k = 0; k < weak.size(); ++k) remeasure(weak, k);

  // Merge: drop the weakest until every point passes both thresholds.
  std::vector<SeriesChangePoint> cps = std::move(weak);
  while (!cps.empty()) {
    auto weakest = std::max_element(cps.begin(), cps.end(), [](const auto& a, const auto& b) { return a.pvalue < b.pvalue; });
    if (weakest->pvalue < p) {
      weakest = std::min_element(cps.begin(), cps.end(),
                                 [](const auto& a, const auto& b) { return a.magnitude() < b.magnitude(); });
      if (weakest->magnitude() > settings.min_magnitude) break;
    }
    // The points at the dropped one's place and the next are measured again, as Otava does (its left
    // neighbour keeps the statistics it had up to the dropped point).
    const auto k = static_cast<std::size_t>(weakest - cps.begin());
    cps.erase(weakest);
    if (k < cps.size()) remeasure(cps, k);
    if (k + 1 < cps.size()) remeasure(cps, k + 1);
  }
  return cps;
}

}  // namespace shatter
