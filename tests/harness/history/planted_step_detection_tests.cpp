// find_change_points at its defaults on noisy series, checked for what is known without it: a step of
// 20 % under noise of 1 % (twenty standard deviations) is found where it was planted, and the change
// points of a series depend only on its shape, not on the scale of its noise (the E-statistic scales
// with the values and the t-test not at all, so at min_magnitude 0 a + b x, b > 0, gives the points of
// x). A step-free series is not free of change points at the defaults (docs/history.md, "Detection on
// synthetic series"): the second test does not ask it to be. The series are those of
// benchmarks/change_point_detection_benchmarks.cpp: 100 points at level 100, normal noise of standard
// deviation cv x the level drawn from std::mt19937_64.

#include "harness/history/change_points.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

using namespace shatter;

namespace {

/// 100 values at level 100, times (1 + step) from index `step_from` on, each with normal noise of
/// standard deviation cv x its level (Box-Muller over std::mt19937_64: the same on every standard library).
std::vector<double> noisy_series(double step, double cv, std::size_t step_from, std::uint64_t seed) {
  std::mt19937_64 bits(seed);
  const auto uniform = [&] { return static_cast<double>(bits() >> 11) * 0x1.0p-53; };
  std::vector<double> series(100);
  for (std::size_t i = 0; i < series.size(); i += 2) {
    const double radius = std::sqrt(-2.0 * std::log(1.0 - uniform()));
    const double angle = 2.0 * std::numbers::pi * uniform();
    const double noise[2] = {radius * std::cos(angle), radius * std::sin(angle)};
    for (std::size_t k = 0; k < 2; ++k) {
      const double level = i + k < step_from ? 100.0 : 100.0 * (1.0 + step);
      series[i + k] = level * (1.0 + cv * noise[k]);
    }
  }
  return series;
}

}  // namespace

TEST_CASE("planted step: a 20 % step under 1 % noise is found at its index in every seed",
          "[history][change-points][planted-step]") {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    INFO("seed " << seed);
    const std::vector<SeriesChangePoint> cps = find_change_points(noisy_series(0.20, 0.01, 60, seed), {});
    const auto step = std::find_if(cps.begin(), cps.end(), [](const SeriesChangePoint& cp) { return cp.index == 60; });
    REQUIRE(step != cps.end());
    CHECK(step->mean_after / step->mean_before == Approx(1.20).epsilon(0.01));
    CHECK(step->pvalue < 1e-10);
  }
}

TEST_CASE("planted step: a step-free series has the same change points under 1 % and 10 % noise",
          "[history][change-points][planted-step]") {
  for (std::uint64_t seed = 1000; seed < 1020; ++seed) {
    INFO("seed " << seed);
    const std::vector<SeriesChangePoint> low = find_change_points(noisy_series(0.0, 0.01, 100, seed), {});
    const std::vector<SeriesChangePoint> high = find_change_points(noisy_series(0.0, 0.10, 100, seed), {});
    REQUIRE(low.size() == high.size());
    for (std::size_t k = 0; k < low.size(); ++k) {
      CHECK(low[k].index == high[k].index);
      CHECK(low[k].pvalue == Approx(high[k].pvalue).epsilon(1e-6));
      CHECK(low[k].pvalue < 0.001);
    }
  }
}
