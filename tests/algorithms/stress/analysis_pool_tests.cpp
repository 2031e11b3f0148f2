// The pool of analysed factors (analysis_pool.h) and the solved systems beside it (solved_systems.h),
// as a solver's memory holds them: the same pattern with other values reuses the analysis, bit for bit
// (the ordering and symbolic factor depend on the pattern alone), another pattern never reuses, and the
// pool stays within its bounds. The reuse by a whole solver is in strength_criterion_solver_tests.cpp.
#include "algorithms/stress/rigid_body_spring/analysis_pool.h"
#include "algorithms/stress/rigid_body_spring/solved_systems.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

#include <numeric>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

/// The displacements (6 #nodes) of `g` under its own weight, solved as one component with `memory`.
std::vector<double> solve_whole(const SupportGraph& g, const Material& material, SolverMemory& memory) {
  std::vector<int> nodes(g.nodes.size()), bonds(g.bonds.size());
  std::iota(nodes.begin(), nodes.end(), 0);
  std::iota(bonds.begin(), bonds.end(), 0);
  std::vector<double> displacements(6 * g.nodes.size(), 0.0);
  std::vector<BondForces> forces(g.bonds.size());
  const SolverReport report = solve_component(g, nodes, bonds, node_loads(g, Loads{}, material), material,
                                              SpringSolverSettings{}, memory, displacements, forces);
  CHECK(report.converged);
  return displacements;
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

TEST_CASE("analysis pool: the same pattern with other stiffness values reuses the analysis, bit for bit", "[stress][von-mises]") {
  const SupportGraph g = block_wall(12, 9);
  Material stiffer;
  stiffer.young_modulus *= 2.5;  // every value of K changes, its pattern does not
  SolverMemory memory;
  solve_whole(g, Material{}, memory);
  const std::size_t analyses = memory.analyses.reuses(), systems = memory.systems.reuses();
  const std::vector<double> warm = solve_whole(g, stiffer, memory);
  CHECK(memory.analyses.reuses() > analyses);
  CHECK(memory.systems.reuses() == systems);
  SolverMemory empty;
  CHECK(solve_whole(g, stiffer, empty) == warm);  // exact: the same factorisation, the same round-off

  SECTION("another graph with as many nodes reuses neither") {
    const SupportGraph other = block_wall(9, 12);  // the same node count, another pattern
    REQUIRE(other.node_count() == g.node_count());
    const std::size_t reused = memory.analyses.reuses(), solved = memory.systems.reuses();
    const std::vector<double> first = solve_whole(other, stiffer, memory);
    CHECK(memory.analyses.reuses() == reused);
    CHECK(memory.systems.reuses() == solved);
    SolverMemory fresh;
    CHECK(solve_whole(other, stiffer, fresh) == first);
  }
}

TEST_CASE("analysis pool: bounded, oldest pattern dropped first", "[stress]") {
  AnalysisPool pool;
  const auto analysed = [&pool](int n) {
    const Eigen::SparseMatrix<double> lower = path_lower(n);
    FactorPattern pattern(lower, {});
    std::optional<SparseCholesky> f = pool.take(pattern, lower);
    REQUIRE(f.has_value());
    REQUIRE(f->factorize(lower));
    pool.keep(std::move(pattern), std::move(*f));
  };
  for (int n = 10; n < 10 + static_cast<int>(kMaxPooledFactors) + 1; ++n) analysed(n);  // one more than fits
  CHECK(pool.reuses() == 0);
  analysed(11);  // still pooled
  CHECK(pool.reuses() == 1);
  analysed(10);  // the oldest, dropped
  CHECK(pool.reuses() == 1);

  SECTION("the same pattern with other node groups is another analysis") {
    const Eigen::SparseMatrix<double> lower = path_lower(12);
    const std::vector<int> groups{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5};
    FactorPattern grouped(lower, groups);
    CHECK_FALSE(grouped == FactorPattern(lower, {}));
    std::optional<SparseCholesky> f = pool.take(grouped, lower);
    REQUIRE(f.has_value());
    CHECK(pool.reuses() == 1);
  }

  SECTION("two pools never see each other's factors") {
    AnalysisPool other;
    const Eigen::SparseMatrix<double> lower = path_lower(11);  // pooled in `pool` above
    std::optional<SparseCholesky> f = other.take(FactorPattern(lower, {}), lower);
    REQUIRE(f.has_value());
    CHECK(other.reuses() == 0);
  }
}
