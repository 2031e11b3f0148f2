// Propagation: failure order, falling clusters, anchoring after breaks, no NaN, bad inputs.
#include "tests/support/builtin_registries.h"
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

constexpr double kRho = 2400.0, kG = 9.81, kL = 4.0, kB = 0.4, kH = 0.6;

int bond_at_x(const SupportGraph& g, double x) {
  for (int i = 0; i < g.bond_count(); ++i)
    if (std::abs(g.bonds[static_cast<std::size_t>(i)].centroid.x() - x) < 1e-9) return i;
  FAIL("no bond at " << x);
  return -1;
}

bool all_finite(const StressResult& r) {
  for (const BondStress& s : r.bonds)
    for (const double v : {s.normal_force, s.shear_force, s.bending_moment, s.torsion, s.sigma, s.tau, s.utilization})
      if (!std::isfinite(v)) return false;
  for (const double v : r.displacements)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

TEST_CASE("propagation: a tensile strength below the root stress breaks the root and drops the span", "[stress][propagation]") {
  const SupportGraph g = graph_of(sliced_box({kL, kB, kH}, {kL / 2, 0, 0}, planes_at(0, even_cuts(0, kL, 8))),
                                  {box_region({-1, -1, -1}, {0.001, 1, 1})}, kRho);
  const double x_root = kL / 8;
  const double root_sigma = kRho * kG * kB * kH * (kL - x_root) * (kL - x_root) / 2 * (kH / 2) / (kB * kH * kH * kH / 12);
  Material weak;
  weak.density = kRho;
  weak.tensile_strength = 0.99 * root_sigma;
  for (const Criterion criterion : {Criterion::tresca, Criterion::von_mises}) {
    const StrengthCriterionModel model(criterion);
    Result<PropagationResult> r = propagate(model, g, Loads{}, weak);
    REQUIRE(r.ok());
    REQUIRE(r->break_order.size() == 1);
    CHECK(r->break_order[0] == std::vector<int>{bond_at_x(g, x_root)});
    REQUIRE(r->result.falling_clusters.size() == 1);
    CHECK(r->result.falling_clusters[0].size() == 7);  // every slab but the anchored one, as one cluster
    CHECK(all_finite(r->result));
  }
}

TEST_CASE("propagation: a broken bond in the middle of a fixed-fixed beam leaves two anchored cantilevers", "[stress][propagation]") {
  const double t = kL * 1e-5;
  std::vector<double> cuts = even_cuts(0, kL, 8);
  cuts.insert(cuts.begin(), 0.0);
  cuts.push_back(kL);
  const SupportGraph g = graph_of(sliced_box({kL + 2 * t, kB, kH}, {kL / 2, 0, 0}, planes_at(0, cuts)),
                                  {box_region({-1, -1, -1}, {-t / 2, 1, 1}), box_region({kL + t / 2, -1, -1}, {kL + 1, 1, 1})},
                                  kRho);
  const StrengthCriterionModel model(Criterion::von_mises);
  Material m;
  m.density = kRho;
  const std::vector<int> broken = {bond_at_x(g, kL / 2)};
  Result<PropagationResult> r = propagate(model, g, Loads{}, m, broken);
  REQUIRE(r.ok());
  CHECK(r->rounds == 0);
  CHECK(r->result.falling_clusters.empty());
  CHECK(r->result.bonds[static_cast<std::size_t>(broken[0])].broken);
  // Each half is now a cantilever of length L / 2: statics fixes its moments.
  const double w = kRho * kG * kB * kH;
  for (const double x : {0.0, kL / 8, kL / 4, 3 * kL / 8}) {
    const BondStress& s = r->result.bonds[static_cast<std::size_t>(bond_at_x(g, x))];
    const double lever = kL / 2 - x;
    CHECK(std::abs(s.bending_moment - w * lever * lever / 2) < 1e-9 * w * kL * kL);
    const BondStress& mirror = r->result.bonds[static_cast<std::size_t>(bond_at_x(g, kL - x))];
    CHECK(std::abs(mirror.bending_moment - w * lever * lever / 2) < 1e-9 * w * kL * kL);
  }
}

TEST_CASE("propagation: re-solving only the touched component leaves the others bit for bit", "[stress][propagation]") {
  // Two separate anchored columns side by side; breaking a bond in one must not re-solve the other.
  std::vector<Plane> planes = planes_at(2, even_cuts(0, 2.0, 4));
  planes.push_back(planes_at(0, {0.0})[0]);
  const std::vector<Fragment> fragments = sliced_box({1.0, 0.5, 2.0}, {0, 0, 1.0}, planes);
  std::vector<Fragment> apart;
  for (Fragment f : fragments) {  // pull the x > 0 column 1 m away
    if (f.mass.centroid.x() > 0) {
      for (Vec3& v : f.mesh.vertices) v.x() += 1.0;
      f.mass.centroid.x() += 1.0;
    }
    apart.push_back(f);
  }
  const SupportGraph g = graph_of(apart, {box_region({-5, -5, -5}, {5, 5, 0.001})}, kRho);
  REQUIRE(g.bond_count() == 6);
  const StrengthCriterionModel model(Criterion::von_mises);
  const std::unique_ptr<StressSolver> solver = model.make_solver(g, Material{});
  Result<StressResult> first = solver->evaluate(Loads{});
  REQUIRE(first.ok());
  StressResult next = first.value();
  int left = -1;
  for (int i = 0; i < g.bond_count(); ++i)  // the left column's top bond: the rest stays anchored
    if (g.bonds[static_cast<std::size_t>(i)].centroid.x() < 0 &&
        (left < 0 || g.bonds[static_cast<std::size_t>(i)].centroid.z() > g.bonds[static_cast<std::size_t>(left)].centroid.z()))
      left = i;
  next.bonds[static_cast<std::size_t>(left)].broken = true;
  const Bond& e = g.bonds[static_cast<std::size_t>(left)];
  Result<StressResult> second = solver->reevaluate(Loads{}, next, std::vector<int>{e.a, e.b});
  REQUIRE(second.ok());
  CHECK(second->report.solves == 1);
  CHECK(second->falling_clusters.size() == 1);
  for (int i = 0; i < g.bond_count(); ++i)
    if (g.bonds[static_cast<std::size_t>(i)].centroid.x() > 0)
      CHECK(second->bonds[static_cast<std::size_t>(i)].sigma == first->bonds[static_cast<std::size_t>(i)].sigma);
}

TEST_CASE("propagation: a structure with no anchor falls whole, never solved, without NaN", "[stress][propagation]") {
  const SupportGraph g = graph_of(sliced_box({kL, kB, kH}, {kL / 2, 0, 0}, planes_at(0, even_cuts(0, kL, 4))), {}, kRho);
  for (const char* name : {"connection-count", "tresca", "von-mises"}) {
    Result<std::unique_ptr<StressModel>> model = test::builtin_registries().stress_models.create(name);
    REQUIRE(model.ok());
    Result<PropagationResult> r = propagate(**model, g, Loads{}, Material{});
    REQUIRE(r.ok());
    CHECK(r->report.solves == 0);
    REQUIRE(r->result.falling_clusters.size() == 1);
    CHECK(r->result.falling_clusters[0] == std::vector<int>{0, 1, 2, 3});
    CHECK(all_finite(r->result));
  }
}

TEST_CASE("stress-model: bad materials, loads and names are errors", "[stress]") {
  const SupportGraph g = graph_of(sliced_box({kL, kB, kH}, {kL / 2, 0, 0}, planes_at(0, {2.0})),
                                  {box_region({-1, -1, -1}, {0.001, 1, 1})}, kRho);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::string& name : test::builtin_registries().stress_models.names()) {
    Result<std::unique_ptr<StressModel>> model = test::builtin_registries().stress_models.create(name);
    REQUIRE(model.ok());
    CHECK((*model)->name() == name);
    for (int field = 0; field < 6; ++field) {
      Material m;
      if (field == 0) m.density = -2400.0;
      if (field == 1) m.young_modulus = 0.0;
      if (field == 2) m.poisson_ratio = 0.5;
      if (field == 3) m.tensile_strength = nan;
      if (field == 4) m.compressive_strength = -1.0;
      if (field == 5) m.shear_strength = std::numeric_limits<double>::infinity();
      CHECK_FALSE((*model)->evaluate(g, Loads{}, m).ok());
    }
    Loads bad;
    bad.point_loads.push_back({7, Vec3::Zero(), Vec3::UnitZ()});
    CHECK_FALSE((*model)->evaluate(g, bad, Material{}).ok());
    bad.point_loads = {{0, Vec3::Zero(), Vec3(nan, 0, 0)}};
    CHECK_FALSE((*model)->evaluate(g, bad, Material{}).ok());
  }
  Result<std::unique_ptr<StressModel>> unknown = test::builtin_registries().stress_models.create("rankine");
  REQUIRE_FALSE(unknown.ok());
  CHECK(unknown.error().message.find("von-mises") != std::string::npos);
}
