// The Mann-Whitney U test against values computed by hand.

#include "harness/compare/mann_whitney.h"

#include <catch2/catch.hpp>

#include <vector>

using shatter::mann_whitney_u;
using shatter::smallest_p_value;

TEST_CASE("mann-whitney: exact p-values of small samples without ties", "[compare]") {
  // x entirely below y: U = 0; P(U <= 0) = 1 / C(6, 3) = 1/20, two-sided 0.1.
  const std::vector<double> a{1, 2, 3}, b{4, 5, 6};
  const auto r = mann_whitney_u(a, b);
  CHECK(r.exact);
  CHECK(r.u == 0.0);
  CHECK(r.p_value == Approx(0.1).epsilon(1e-12));
  // Five against five, separated: 2 / C(10, 5) = 2 / 252.
  const std::vector<double> c{1, 2, 3, 4, 5}, d{6, 7, 8, 9, 10};
  CHECK(mann_whitney_u(c, d).p_value == Approx(2.0 / 252.0).epsilon(1e-12));
  CHECK(mann_whitney_u(d, c).u == 25.0);
  // Interleaved: x = {1, 3, 5}, y = {2, 4, 6}: U = 3 (3 > 2, 5 > 2, 5 > 4). The null counts of U for
  // n = m = 3 are 1, 1, 2, 3, 3, 3, 3, 2, 1, 1 (of 20): P(U <= 3) = 7/20, two-sided 0.7.
  const std::vector<double> e{1, 3, 5}, f{2, 4, 6};
  const auto g = mann_whitney_u(e, f);
  CHECK(g.u == 3.0);
  CHECK(g.p_value == Approx(0.7).epsilon(1e-12));
}

TEST_CASE("mann-whitney: ties use mid-ranks and the tie-corrected normal approximation", "[compare]") {
  // x = {1, 2, 2}, y = {2, 3, 4}: the three 2s share rank 3, R_x = 1 + 3 + 3 = 7, U = 7 - 6 = 1.
  // Var = n1 n2 / 12 (n + 1 - sum(t^3 - t) / (n (n - 1))) = 9/12 (7 - 24/30) = 4.65;
  // z = (|1 - 4.5| - 0.5) / sqrt(4.65); p = erfc(z / sqrt 2) = 0.164159728...
  const std::vector<double> a{1, 2, 2}, b{2, 3, 4};
  const auto r = mann_whitney_u(a, b);
  CHECK_FALSE(r.exact);
  CHECK(r.u == 1.0);
  CHECK(r.p_value == Approx(0.16415972847851523).epsilon(1e-12));
  // All equal: no evidence of a difference.
  const std::vector<double> same{5, 5, 5};
  CHECK(mann_whitney_u(same, same).p_value == 1.0);
}

TEST_CASE("mann-whitney: the smallest reachable p-value says when a test can never fire", "[compare]") {
  CHECK(smallest_p_value(3, 3) == Approx(0.1));
  CHECK(smallest_p_value(5, 5) == Approx(2.0 / 252.0));
  CHECK(smallest_p_value(9, 9) < 0.01);
  CHECK(smallest_p_value(4, 4) > 0.01);
}
