// One bond's stresses from its forces (strength_criterion.h) against the formulas for a rectangular
// section: sigma = |N| / A + |M| c / I, and which fibre governs, also where pure bending leaves the
// two fibres equal up to the solve's round-off.

#include "algorithms/stress/strength_criterion.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace shatter;

namespace {

/// A b x h rectangle (b along axis_1, h along axis_2), with its hull as the section.
Bond rectangle_bond(double b, double h) {
  Bond e;
  e.area = b * h;
  e.moment_1 = b * h * h * h / 12.0;  // about axis_1: the fibres are at +-h/2 along axis_2
  e.moment_2 = h * b * b * b / 12.0;
  e.polar_moment = e.moment_1 + e.moment_2;
  e.fibre_1 = h / 2;
  e.fibre_2 = b / 2;
  e.radius = std::hypot(b, h) / 2;
  e.length = 1.0;
  e.section = {Vec2(-b / 2, -h / 2), Vec2(b / 2, -h / 2), Vec2(b / 2, h / 2), Vec2(-b / 2, h / 2)};
  return e;
}

}  // namespace

TEST_CASE("strength criterion: bending and axial stress of a rectangular section", "[stress]") {
  const double b = 0.3, h = 0.5, moment = 2e4;
  const Bond e = rectangle_bond(b, h);
  const double bending = moment * (h / 2) / e.moment_1;
  for (const bool hull : {true, false}) {
    Bond bond = e;
    if (!hull) bond.section.clear();  // the fibre distances instead of the hull
    INFO("hull " << hull);
    BondForces f;
    f.moment_1 = moment;
    f.normal = -1e4;  // compression adds to the compressed fibre
    BondStress s = bond_stress(bond, f, Material{}, Criterion::von_mises);
    CHECK(s.sigma == Approx(bending + 1e4 / e.area).epsilon(1e-12));
    CHECK_FALSE(s.tensile);
    f.normal = 1e4;  // tension adds to the stretched fibre
    s = bond_stress(bond, f, Material{}, Criterion::von_mises);
    CHECK(s.sigma == Approx(bending + 1e4 / e.area).epsilon(1e-12));
    CHECK(s.tensile);
  }
}

TEST_CASE("strength criterion: pure bending is tensile whatever the sign of a round-off axial force", "[stress]") {
  const Bond e = rectangle_bond(0.3, 0.5);
  const double moment = 2e4;
  for (const double axial : {0.0, -0.0, 1e-12, -1e-12, -1e-8}) {
    INFO("axial force " << axial << " N");
    BondForces f;
    f.moment_1 = moment;
    f.normal = axial;
    const BondStress s = bond_stress(e, f, Material{}, Criterion::tresca);
    CHECK(s.tensile);
    CHECK(s.sigma == Approx(moment * 0.25 / e.moment_1).epsilon(1e-12));
  }
  // A compression well above round-off (here 1e-6 of the bending stress) governs.
  BondForces f;
  f.moment_1 = moment;
  f.normal = -1e-6 * moment * 0.25 / e.moment_1 * e.area;
  CHECK_FALSE(bond_stress(e, f, Material{}, Criterion::tresca).tensile);
}
