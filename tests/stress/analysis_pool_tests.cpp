// The solver's reuse: the split and factors of a K solved before (linear_solve.h) and the pool of
// analysed factors (analysis_pool.h). Reuse gives bit for bit the results of a fresh solve (the same K
// gives the same factors; the ordering and symbolic factor depend on the pattern alone), another
// pattern never reuses, and the pool stays within its bounds.
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/analysis_pool.h"
#include "algorithms/stress/rigid_body_spring/linear_solve.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
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
}

/// A small SPD pattern: the lower triangle of a path graph with `n` unknowns.
Eigen::SparseMatrix<double> path_lower(int n) {
  Eigen::SparseMatrix<double> m(n, n);
  for (int i = 0; i < n; ++i) {
    m.insert(i, i) = 4.0;
    if (i + 1 < n) m.insert(i + 1, i) = -1.0;
  }
  m.makeCompressed();
  return m;
}

}  // namespace

TEST_CASE("solver reuse: the same structure under other loads reuses split and factors, bit for bit", "[stress][von-mises]") {
  const SupportGraph g = block_wall(12, 9);
  const StrengthCriterionModel model(Criterion::von_mises);
  Loads pushed;
  pushed.point_loads.push_back(PointLoad{40, g.nodes[40].centroid, Vec3(3e4, 0.0, -1e4)});
  forget_solver_reuse();
  const std::size_t systems = solved_system_reuses();
  Result<StressResult> first = model.evaluate(g, Loads{}, Material{});
  REQUIRE(first.ok());
  CHECK(solved_system_reuses() == systems);  // nothing kept yet
  Result<StressResult> warm = model.evaluate(g, pushed, Material{});
  REQUIRE(warm.ok());
  CHECK(solved_system_reuses() == systems + 1);
  forget_solver_reuse();
  Result<StressResult> cold = model.evaluate(g, pushed, Material{});
  REQUIRE(cold.ok());
  check_identical(*warm, *cold);
  CHECK(warm->report.residual < 1e-12);
  CHECK(warm->displacements != first->displacements);  // the load did change the answer
}

TEST_CASE("analysis pool: the same pattern with other stiffness values reuses the analysis, bit for bit", "[stress][von-mises]") {
  const SupportGraph g = block_wall(12, 9);
  const StrengthCriterionModel model(Criterion::von_mises);
  Material stiffer;
  stiffer.young_modulus *= 2.5;  // every value of K changes, its pattern does not
  forget_solver_reuse();
  REQUIRE(model.evaluate(g, Loads{}, Material{}).ok());
  const std::size_t analyses = analysed_reuses(), systems = solved_system_reuses();
  Result<StressResult> warm = model.evaluate(g, Loads{}, stiffer);
  REQUIRE(warm.ok());
  CHECK(analysed_reuses() > analyses);
  CHECK(solved_system_reuses() == systems);
  forget_solver_reuse();
  Result<StressResult> cold = model.evaluate(g, Loads{}, stiffer);
  REQUIRE(cold.ok());
  check_identical(*warm, *cold);

  SECTION("another graph with as many nodes reuses neither") {
    const SupportGraph other = block_wall(9, 12);  // the same node count, another pattern
    REQUIRE(other.node_count() == g.node_count());
    const std::size_t reused = analysed_reuses(), solved = solved_system_reuses();
    Result<StressResult> first = model.evaluate(other, Loads{}, stiffer);
    REQUIRE(first.ok());
    CHECK(analysed_reuses() == reused);
    CHECK(solved_system_reuses() == solved);
    forget_solver_reuse();
    Result<StressResult> fresh = model.evaluate(other, Loads{}, stiffer);
    REQUIRE(fresh.ok());
    check_identical(*first, *fresh);
  }
}

TEST_CASE("analysis pool: a cascade run again reuses its analyses and breaks the same bonds", "[stress][propagation]") {
  const SupportGraph g = block_wall(12, 9);
  const StrengthCriterionModel model(Criterion::von_mises);
  Material weak;
  weak.tensile_strength = 2e4;
  const std::vector<int> hole = g.node_bonds[static_cast<std::size_t>(12 + 6)];  // second row, middle
  forget_solver_reuse();
  Result<PropagationResult> cold = propagate(model, g, Loads{}, weak, hole);
  REQUIRE(cold.ok());
  REQUIRE(cold->rounds >= 2);  // the reused cascade pattern is in play
  const std::size_t before = analysed_reuses(), solved = solved_system_reuses();
  Result<PropagationResult> warm = propagate(model, g, Loads{}, weak, hole);
  REQUIRE(warm.ok());
  CHECK(analysed_reuses() > before);     // the cascade's own pattern (CascadeSolver)
  CHECK(solved_system_reuses() > solved);  // the first round's components, solved as before
  CHECK(warm->break_order == cold->break_order);
  check_identical(warm->result, cold->result);
}

TEST_CASE("analysis pool: bounded, oldest pattern dropped first", "[stress]") {
  forget_solver_reuse();
  const std::size_t start = analysed_reuses();
  const auto analysed = [](int n) {
    const Eigen::SparseMatrix<double> lower = path_lower(n);
    FactorPattern pattern(lower, {});
    std::optional<SparseCholesky> f = take_analysed(pattern, lower);
    REQUIRE(f.has_value());
    REQUIRE(f->factorize(lower));
    keep_analysed(std::move(pattern), std::move(*f));
  };
  for (int n = 10; n < 10 + static_cast<int>(kMaxPooledFactors) + 1; ++n) analysed(n);  // one more than fits
  CHECK(analysed_reuses() == start);
  analysed(11);  // still pooled
  CHECK(analysed_reuses() == start + 1);
  analysed(10);  // the oldest, dropped
  CHECK(analysed_reuses() == start + 1);

  SECTION("the same pattern with other node groups is another analysis") {
    const Eigen::SparseMatrix<double> lower = path_lower(12);
    const std::vector<int> groups{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5};
    const std::size_t reused = analysed_reuses();
    FactorPattern grouped(lower, groups);
    CHECK_FALSE(grouped == FactorPattern(lower, {}));
    std::optional<SparseCholesky> f = take_analysed(grouped, lower);
    REQUIRE(f.has_value());
    CHECK(analysed_reuses() == reused);
  }
}
