// Sample statistics (DESIGN.md sections 6 and 8): hand-computed values with type-7 percentiles.

#include "harness/results/sample_statistics.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace shatter;

TEST_CASE("sample statistics: 1 to 10", "[results]") {
  const std::vector<double> x = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  const SampleStatistics s = sample_statistics(x);
  CHECK(s.count == 10);
  CHECK(s.mean == Approx(5.5));
  CHECK(s.median == Approx(5.5));
  CHECK(s.p95 == Approx(9.55));  // h = 9 * 0.95 = 8.55: x[8] + 0.55 (x[9] - x[8])
  CHECK(s.p99 == Approx(9.91));  // h = 8.91
  CHECK(s.min == 1.0);
  CHECK(s.max == 10.0);
}

TEST_CASE("sample statistics: unsorted input gives the same figures", "[results]") {
  const std::vector<double> x = {7, 3, 10, 1, 9, 5, 2, 8, 6, 4};
  const SampleStatistics s = sample_statistics(x);
  CHECK(s.count == 10);
  CHECK(s.mean == Approx(5.5));
  CHECK(s.median == Approx(5.5));
  CHECK(s.p95 == Approx(9.55));
  CHECK(s.p99 == Approx(9.91));
  CHECK(s.min == 1.0);
  CHECK(s.max == 10.0);
  CHECK(median_of(x) == Approx(5.5));
}

TEST_CASE("sample statistics: odd count, median is the middle value", "[results]") {
  const std::vector<double> x = {4.0, 1.0, 100.0};
  const SampleStatistics s = sample_statistics(x);
  CHECK(s.median == 4.0);
  CHECK(s.mean == Approx(35.0));
  CHECK(s.p95 == Approx(90.4));  // h = 1.9: 4 + 0.9 * 96
  CHECK(median_of(x) == 4.0);
}

TEST_CASE("sample statistics: a single value is every figure", "[results]") {
  const std::vector<double> x = {2.5};
  const SampleStatistics s = sample_statistics(x);
  CHECK(s.count == 1);
  CHECK(s.mean == 2.5);
  CHECK(s.median == 2.5);
  CHECK(s.p95 == 2.5);
  CHECK(s.p99 == 2.5);
  CHECK(s.min == 2.5);
  CHECK(s.max == 2.5);
  CHECK(median_of(x) == 2.5);
}

TEST_CASE("sample statistics: no samples give zeros, not NaN", "[results]") {
  const SampleStatistics s = sample_statistics({});
  CHECK(s.count == 0);
  CHECK(s.mean == 0.0);
  CHECK(s.median == 0.0);
  CHECK(s.p95 == 0.0);
  CHECK(s.p99 == 0.0);
  CHECK(s.min == 0.0);
  CHECK(s.max == 0.0);
  CHECK(median_of({}) == 0.0);
}

TEST_CASE("sample statistics: quantiles at the ends are min and max", "[results]") {
  const std::vector<double> sorted = {1.0, 2.0, 4.0, 8.0};
  CHECK(quantile_of_sorted(sorted, 0.0) == 1.0);
  CHECK(quantile_of_sorted(sorted, 1.0) == 8.0);
  CHECK(quantile_of_sorted(sorted, 0.5) == Approx(3.0));
}
