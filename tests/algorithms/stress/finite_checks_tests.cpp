// The finiteness checks of the stress results (stress_model.h): an exponent-bit test, checked here
// against std::isfinite on the values where the two could part: infinities, NaNs of either sign and
// payload, the largest and smallest doubles, subnormals and signed zeros.
#include "algorithms/stress/stress_model.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace shatter;

namespace {

std::vector<double> edge_values() {
  using limits = std::numeric_limits<double>;
  return {0.0,          -0.0,           1.0,          -1.0,           limits::max(),  -limits::max(),
          limits::min(), limits::denorm_min(), -limits::denorm_min(), limits::infinity(), -limits::infinity(),
          limits::quiet_NaN(), -limits::quiet_NaN(), limits::signaling_NaN(), std::nan("7"), 1e308 * 10.0};
}

}  // namespace

TEST_CASE("finite checks: the exponent-bit test agrees with std::isfinite", "[stress][finite]") {
  for (const double x : edge_values()) {
    INFO(x);
    CHECK((nonfinite_bit(x) == 0) == std::isfinite(x));
    const std::vector<double> one{1.0, x, 2.0};
    CHECK(values_finite(one) == std::isfinite(x));
  }
  CHECK(values_finite(std::vector<double>{}));
}

TEST_CASE("finite checks: one bond figure that is not finite makes the bond, and the result, not finite",
          "[stress][finite]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double BondStress::*figures[] = {&BondStress::normal_force, &BondStress::shear_force, &BondStress::bending_moment,
                                   &BondStress::torsion,      &BondStress::sigma,       &BondStress::tau,
                                   &BondStress::utilization};
  CHECK(bond_finite(BondStress{}));
  for (double BondStress::*figure : figures)
    for (const double bad : {inf, -inf, nan}) {
      BondStress b;
      b.*figure = bad;
      CHECK_FALSE(bond_finite(b));
      StressResult r;
      r.bonds = {BondStress{}, b};
      r.displacements = {0.0, 1.0};
      CHECK_FALSE(judge_finite(r));
      CHECK_FALSE(r.report.finite);
      CHECK_FALSE(r.report.converged);
    }
  StressResult clean;
  clean.bonds = {BondStress{.normal_force = -std::numeric_limits<double>::max(), .broken = true}};
  clean.displacements = {std::numeric_limits<double>::denorm_min()};
  CHECK(judge_finite(clean));
  CHECK(clean.report.converged);
}
