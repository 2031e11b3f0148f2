// The decoupled supernodal solve against Eigen's SimplicialLDLT on the whole system, on a block wall
// large enough (2,898 unknowns) to split into blocks: displacements to 1e-9 relative, and the same
// cascade (bonds broken per round, falling clusters) exactly.
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "tests/stress/structures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace shatter;
using namespace shatter::test;

namespace {

/// Max |a - b| / max |b| over the displacements.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

/// The bonds of the wall's block nearest (x, z).
std::vector<int> bonds_of_block_at(const SupportGraph& g, double x, double z) {
  int target = 0;
  double best = 1e300;
  for (int v = 0; v < g.node_count(); ++v) {
    const Vec3& c = g.nodes[static_cast<std::size_t>(v)].centroid;
    const double d = std::abs(c.x() - x) + std::abs(c.z() - z);
    if (d < best) best = d, target = v;
  }
  return g.node_bonds[static_cast<std::size_t>(target)];
}

SpringSolverSettings reference_settings() {
  SpringSolverSettings s;
  s.reference = true;
  return s;
}

}  // namespace

TEST_CASE("rigid-body-spring: decoupled supernodal solve matches SimplicialLDLT on a 23 x 22 wall", "[stress][von-mises][tresca]") {
  const SupportGraph g = block_wall(23, 22);
  for (const Criterion criterion : {Criterion::von_mises, Criterion::tresca}) {
    const StrengthCriterionModel fast(criterion);
    const StrengthCriterionModel reference(criterion, reference_settings());

    Result<StressResult> a = fast.evaluate(g, Loads{}, Material{});
    Result<StressResult> b = reference.evaluate(g, Loads{}, Material{});
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(a->report.unknowns == 6 * 22 * 23 - 6 * 23);  // the bottom row is anchored
    CHECK(a->report.converged);
    CHECK(a->report.residual < 1e-12);
    CHECK(b->report.residual < 1e-12);
    CHECK(relative_difference(a->displacements, b->displacements) < 1e-9);
    double worst = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < a->bonds.size(); ++i) {
      worst = std::max(worst, std::abs(a->bonds[i].utilization - b->bonds[i].utilization));
      peak = std::max(peak, b->bonds[i].utilization);
    }
    CHECK(worst < 1e-9 * peak);

    // The benchmark's cascade: a block of the second row knocked out, weak mortar.
    Material weak;
    weak.tensile_strength = 2e4;
    const std::vector<int> hole = bonds_of_block_at(g, 11.25 / 2, 0.75);  // as benchmarks/stress_benchmarks.cpp
    Result<PropagationResult> pa = propagate(fast, g, Loads{}, weak, hole);
    Result<PropagationResult> pb = propagate(reference, g, Loads{}, weak, hole);
    REQUIRE(pa.ok());
    REQUIRE(pb.ok());
    CHECK(pa->rounds >= 5);
    CHECK(pa->report.converged);
    CHECK(pa->break_order == pb->break_order);
    CHECK(pa->result.falling_clusters == pb->result.falling_clusters);
    CHECK(relative_difference(pa->result.displacements, pb->result.displacements) < 1e-9);
  }
}
