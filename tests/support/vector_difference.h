#pragma once
// The difference of two solutions of one system, relative to the reference's largest entry.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shatter::test {

/// max_i |a_i - b_i| / max_i |b_i| (requires equal sizes).
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

}  // namespace shatter::test
