// tresca and von-mises against beam theory and statics: cantilever, column, fixed-fixed beam.
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

constexpr double kRho = 2400.0;
constexpr double kG = 9.81;

double rel(double value, double truth) { return std::abs(value - truth) / std::abs(truth); }

const Bond& bond_at(const SupportGraph& g, int axis, double x, int* index = nullptr) {
  for (int i = 0; i < g.bond_count(); ++i)
    if (std::abs(g.bonds[static_cast<std::size_t>(i)].centroid[axis] - x) < 1e-9) {
      if (index) *index = i;
      return g.bonds[static_cast<std::size_t>(i)];
    }
  FAIL("no bond at " << x);
  return g.bonds.front();
}

Material concrete() {
  Material m;
  m.density = kRho;
  return m;
}

StressResult evaluate(Criterion criterion, const SupportGraph& g, const Loads& loads) {
  const StrengthCriterionModel model(criterion);
  Result<StressResult> r = model.evaluate(g, loads, concrete());
  REQUIRE(r.ok());
  CHECK(r->report.converged);
  CHECK(r->report.residual < 1e-12);
  return std::move(r.value());
}

// Cantilever along x: length L = 4, width b = 0.4 (y), height h = 0.6 (z), root at x = 0.
constexpr double kL = 4.0, kB = 0.4, kH = 0.6;

SupportGraph cantilever(int slabs) {
  return graph_of(sliced_box({kL, kB, kH}, {kL / 2, 0, 0}, planes_at(0, even_cuts(0.0, kL, slabs))),
                  {box_region({-1, -1, -1}, {0.001, 1, 1})}, kRho);
}

}  // namespace

TEST_CASE("von-mises: cantilever under its own weight matches beam theory at every bond", "[stress][tresca][von-mises]") {
  const SupportGraph g = cantilever(8);
  const double w = kRho * kG * kB * kH;  // N/m
  const double inertia = kB * kH * kH * kH / 12.0;
  for (const Criterion criterion : {Criterion::tresca, Criterion::von_mises}) {
    const StressResult r = evaluate(criterion, g, Loads{});
    REQUIRE(r.falling_clusters.empty());
    for (const double x : even_cuts(0.0, kL, 8)) {
      int i = 0;
      bond_at(g, 0, x, &i);
      const BondStress& s = r.bonds[static_cast<std::size_t>(i)];
      const double moment = w * (kL - x) * (kL - x) / 2.0;
      CHECK(rel(s.shear_force, w * (kL - x)) < 1e-9);
      CHECK(rel(s.bending_moment, moment) < 1e-9);
      CHECK(rel(s.sigma, moment * (kH / 2) / inertia) < 1e-9);
      CHECK(std::abs(s.normal_force) < 1e-9 * w * kL);
      CHECK(s.torsion < 1e-9 * moment);
      CHECK(rel(s.tau, w * (kL - x) / (kB * kH)) < 1e-9);
      const double factor = criterion == Criterion::tresca ? 4.0 : 3.0;
      CHECK(rel(s.utilization, std::sqrt(s.sigma * s.sigma + factor * s.tau * s.tau) / concrete().tensile_strength) < 1e-12);
      CHECK(s.tensile);
    }
  }
}

TEST_CASE("tresca: cantilever with an eccentric tip load carries P (L - x) and torsion P e", "[stress][tresca]") {
  const SupportGraph g = cantilever(8);
  int tip = 0;
  for (int v = 0; v < g.node_count(); ++v)
    if (g.nodes[static_cast<std::size_t>(v)].centroid.x() > g.nodes[static_cast<std::size_t>(tip)].centroid.x()) tip = v;
  const double p = 1000.0, e = 0.15;
  Loads loads;
  loads.gravity = Vec3::Zero();
  loads.point_loads.push_back({tip, Vec3(kL, e, 0.0), Vec3(0.0, 0.0, -p)});
  const StressResult r = evaluate(Criterion::tresca, g, loads);
  for (const double x : even_cuts(0.0, kL, 8)) {
    int i = 0;
    bond_at(g, 0, x, &i);
    const BondStress& s = r.bonds[static_cast<std::size_t>(i)];
    CHECK(rel(s.shear_force, p) < 1e-9);
    CHECK(rel(s.bending_moment, p * (kL - x)) < 1e-9);
    CHECK(rel(s.torsion, p * e) < 1e-9);
  }
}

TEST_CASE("von-mises: column under its own weight has axial stress rho g (H - z)", "[stress][von-mises]") {
  const double height = 4.0, side = 0.5;
  const SupportGraph g = graph_of(sliced_box({side, side, height}, {0, 0, height / 2}, planes_at(2, even_cuts(0, height, 8))),
                                  {box_region({-1, -1, -1}, {1, 1, 0.001})}, kRho);
  const StressResult r = evaluate(Criterion::von_mises, g, Loads{});
  for (const double z : even_cuts(0.0, height, 8)) {
    int i = 0;
    bond_at(g, 2, z, &i);
    const BondStress& s = r.bonds[static_cast<std::size_t>(i)];
    CHECK(rel(s.sigma, kRho * kG * (height - z)) < 1e-9);
    CHECK(rel(-s.normal_force, kRho * kG * side * side * (height - z)) < 1e-9);
    CHECK_FALSE(s.tensile);
    CHECK(s.shear_force < 1e-9 * std::abs(s.normal_force));
    CHECK(s.bending_moment < 1e-9 * std::abs(s.normal_force));
  }
}

TEST_CASE("von-mises: fixed-fixed beam end and mid-span moments approach w L^2 / 12 and w L^2 / 24", "[stress][von-mises]") {
  // Span L between two thin anchored end blocks (1e-5 L long); n slabs across the span. Measured: the
  // end moment error is 1 / n^2 (1.56%, 0.39%, 0.099% at 8, 16, 32 slabs), mid-span twice that.
  const double span = 4.0, t = span * 1e-5;
  const double w = kRho * kG * kB * kH;
  double previous_error = 1.0;
  for (const auto& [slabs, tolerance] : {std::pair{8, 0.035}, std::pair{16, 0.009}, std::pair{32, 0.0025}}) {
    std::vector<double> cuts = even_cuts(0.0, span, slabs);
    cuts.insert(cuts.begin(), 0.0);
    cuts.push_back(span);
    const SupportGraph g = graph_of(sliced_box({span + 2 * t, kB, kH}, {span / 2, 0, 0}, planes_at(0, cuts)),
                                    {box_region({-1, -1, -1}, {-t / 2, 1, 1}), box_region({span + t / 2, -1, -1}, {span + 1, 1, 1})},
                                    kRho);
    const StressResult r = evaluate(Criterion::von_mises, g, Loads{});
    int end = 0, mid = 0;
    bond_at(g, 0, 0.0, &end);
    bond_at(g, 0, span / 2, &mid);
    const double end_error = rel(r.bonds[static_cast<std::size_t>(end)].bending_moment, w * span * span / 12.0);
    const double mid_error = rel(r.bonds[static_cast<std::size_t>(mid)].bending_moment, w * span * span / 24.0);
    UNSCOPED_INFO("slabs " << slabs << ": end moment error " << end_error << ", mid-span error " << mid_error);
    CHECK(end_error < tolerance);
    CHECK(mid_error < tolerance);
    CHECK(std::max(end_error, mid_error) < previous_error);
    previous_error = std::max(end_error, mid_error);
    // Statics still hold exactly: each support carries half the weight of the span.
    CHECK(rel(r.bonds[static_cast<std::size_t>(end)].shear_force, w * span / 2.0) < 1e-9);
  }
}
