// The solver of one structure (strength_criterion_solver.h): what it keeps between solves (the split
// and factors of a K solved before, its cascade solver) gives bit for bit what a new solver gives, and
// two solvers never see each other's work.
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_solver.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

void check_identical(const StressResult& a, const StressResult& b) {
  REQUIRE(a.displacements.size() == b.displacements.size());
  CHECK(a.displacements == b.displacements);  // exact: the same factorisation, the same round-off
  REQUIRE(a.bonds.size() == b.bonds.size());
  for (std::size_t i = 0; i < a.bonds.size(); ++i) {
    CHECK(a.bonds[i].utilization == b.bonds[i].utilization);
    CHECK(a.bonds[i].broken == b.bonds[i].broken);
  }
  CHECK(a.falling_clusters == b.falling_clusters);
  CHECK(a.report.solves == b.report.solves);
  CHECK(a.report.residual == b.report.residual);
}

}  // namespace

TEST_CASE("strength-criterion solver: the same structure under other loads reuses split and factors, bit for bit", "[stress][von-mises]") {
  const SupportGraph g = block_wall(12, 9);
  Loads pushed;
  pushed.point_loads.push_back(PointLoad{40, g.nodes[40].centroid, Vec3(3e4, 0.0, -1e4)});
  StrengthCriterionSolver solver(g, Material{}, Criterion::von_mises, SpringSolverSettings{});
  Result<StressResult> first = solver.evaluate(Loads{});
  REQUIRE(first.ok());
  CHECK(solver.memory().systems.reuses() == 0);  // nothing kept yet
  Result<StressResult> warm = solver.evaluate(pushed);
  REQUIRE(warm.ok());
  CHECK(solver.memory().systems.reuses() == 1);
  Result<StressResult> cold = StrengthCriterionSolver(g, Material{}, Criterion::von_mises, SpringSolverSettings{}).evaluate(pushed);
  REQUIRE(cold.ok());
  check_identical(*warm, *cold);
  CHECK(warm->report.residual < 1e-12);
  CHECK(warm->displacements != first->displacements);  // the load did change the answer
}

TEST_CASE("strength-criterion solver: two solvers never see each other's solved systems", "[stress][von-mises]") {
  const SupportGraph g = block_wall(12, 9);
  StrengthCriterionSolver one(g, Material{}, Criterion::von_mises, SpringSolverSettings{});
  StrengthCriterionSolver two(g, Material{}, Criterion::von_mises, SpringSolverSettings{});
  REQUIRE(one.evaluate(Loads{}).ok());
  REQUIRE(one.evaluate(Loads{}).ok());
  CHECK(one.memory().systems.reuses() == 1);  // the first solve's K, kept by `one`
  REQUIRE(two.evaluate(Loads{}).ok());
  CHECK(two.memory().systems.reuses() == 0);  // the same K, not seen by `two`
  CHECK(two.memory().analyses.reuses() == 0);
  CHECK(one.memory().systems.reuses() == 1);  // and `two` took nothing from `one`
}

TEST_CASE("strength-criterion solver: a cascade run again on a kept solver breaks the same bonds, bit for bit", "[stress][propagation]") {
  const SupportGraph g = block_wall(12, 9);
  const StrengthCriterionModel model(Criterion::von_mises);
  Material weak;
  weak.tensile_strength = 2e4;
  const std::vector<int> hole = g.node_bonds[static_cast<std::size_t>(12 + 6)];  // second row, middle
  const std::unique_ptr<StressSolver> kept = model.make_solver(g, weak);
  Result<PropagationResult> first = propagate(*kept, Loads{}, hole);
  REQUIRE(first.ok());
  REQUIRE(first->rounds >= 2);  // the kept cascade solver is in play
  Result<PropagationResult> again = propagate(*kept, Loads{}, hole);
  Result<PropagationResult> fresh = propagate(model, g, Loads{}, weak, hole);
  REQUIRE(again.ok());
  REQUIRE(fresh.ok());
  CHECK(dynamic_cast<const StrengthCriterionSolver&>(*kept).memory().systems.reuses() > 0);  // the first round's K
  for (const PropagationResult* p : {&*again, &*first}) {
    CHECK(p->break_order == fresh->break_order);
    CHECK(p->rounds == fresh->rounds);
    CHECK(p->report.solves == fresh->report.solves);
    check_identical(p->result, fresh->result);
  }

  SECTION("and a smaller event after a larger one, as the pipeline's events come") {
    const std::vector<int> corner = g.node_bonds[static_cast<std::size_t>(12 + 1)];
    Result<PropagationResult> later = propagate(*kept, Loads{}, corner);
    Result<PropagationResult> alone = propagate(model, g, Loads{}, weak, corner);
    REQUIRE(later.ok());
    REQUIRE(alone.ok());
    CHECK(later->break_order == alone->break_order);
    check_identical(later->result, alone->result);
  }
}
