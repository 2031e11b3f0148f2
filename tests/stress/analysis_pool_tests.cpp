// The pool of analysed factors (analysis_pool.h): a reused analysis gives bit for bit the results of a
// fresh one (the ordering and symbolic factor depend on the pattern alone), another pattern never
// reuses, and the pool stays within its bounds.
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/analysis_pool.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "tests/stress/structures.h"

#include <catch2/catch.hpp>

using namespace shatter;
using namespace shatter::test;

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

TEST_CASE("analysis pool: a second evaluation of the same graph reuses the analysis, bit for bit", "[stress][von-mises]") {
  const SupportGraph g = block_wall(12, 9);
  const StrengthCriterionModel model(Criterion::von_mises);
  forget_analysed();
  const std::size_t before = analysed_reuses();
  Result<StressResult> cold = model.evaluate(g, Loads{}, Material{});
  REQUIRE(cold.ok());
  CHECK(analysed_reuses() == before);  // nothing pooled yet
  Result<StressResult> warm = model.evaluate(g, Loads{}, Material{});
  REQUIRE(warm.ok());
  CHECK(analysed_reuses() > before);
  check_identical(*warm, *cold);
  CHECK(warm->report.residual < 1e-12);

  SECTION("another graph with as many nodes does not reuse it") {
    const SupportGraph other = block_wall(9, 12);  // the same node count, another pattern
    REQUIRE(other.node_count() == g.node_count());
    const std::size_t reused = analysed_reuses();
    Result<StressResult> first = model.evaluate(other, Loads{}, Material{});
    REQUIRE(first.ok());
    CHECK(analysed_reuses() == reused);
    forget_analysed();
    Result<StressResult> fresh = model.evaluate(other, Loads{}, Material{});
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
  forget_analysed();
  Result<PropagationResult> cold = propagate(model, g, Loads{}, weak, hole);
  REQUIRE(cold.ok());
  REQUIRE(cold->rounds >= 2);  // the reused cascade pattern is in play
  const std::size_t before = analysed_reuses();
  Result<PropagationResult> warm = propagate(model, g, Loads{}, weak, hole);
  REQUIRE(warm.ok());
  CHECK(analysed_reuses() > before);
  CHECK(warm->break_order == cold->break_order);
  check_identical(warm->result, cold->result);
}

TEST_CASE("analysis pool: bounded, oldest pattern dropped first", "[stress]") {
  forget_analysed();
  const std::size_t start = analysed_reuses();
  const auto analysed = [](int n) {
    const Eigen::SparseMatrix<double> lower = path_lower(n);
    FactorPattern pattern(lower, {});
    std::optional<SupernodalCholesky> f = take_analysed(pattern, lower);
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
    std::optional<SupernodalCholesky> f = take_analysed(grouped, lower);
    REQUIRE(f.has_value());
    CHECK(analysed_reuses() == reused);
  }
}
