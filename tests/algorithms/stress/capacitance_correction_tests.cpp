// The capacitance correction (capacitance_correction.h) against a factorisation of the changed K
// itself, and the exact cascade that uses it against the reference path (SimplicialLDLT on the whole
// K every round): the same bonds broken in the same rounds and the same falling clusters.
#include "algorithms/core/random.h"
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/capacitance_correction.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_solver.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

#include <Eigen/SparseCholesky>

#include <vector>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

/// K's lower triangle (compressed, same pattern whatever is broken: the graph's intact pattern).
Eigen::SparseMatrix<double> lower_of(const Eigen::SparseMatrix<double>& k) {
  Eigen::SparseMatrix<double> lower = k.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  return lower;
}

}  // namespace

TEST_CASE("capacitance correction: solves equal a factorisation of the changed K, on walls with random breaks",
          "[stress][capacitance]") {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const SupportGraph g = block_wall(9, 8);
    GraphStiffness stiffness(g, Material{});
    std::vector<std::uint8_t> include(g.bonds.size(), 1), identity(g.nodes.size(), 0);
    stiffness.assemble(include, identity);
    // The intact K (both triangles kept: the values of the whole pattern, explicit zeros included).
    const Eigen::SparseMatrix<double> base = lower_of(stiffness.matrix());
    std::vector<int> groups(static_cast<std::size_t>(base.cols()));
    for (std::size_t i = 0; i < groups.size(); ++i) groups[i] = static_cast<int>(i / 6);
    NodeBlockCholesky factor;  // 6 unknowns per node
    REQUIRE(factor.analyze(base, groups));
    REQUIRE(factor.factorize(base));
    CapacitanceCorrection correction;
    correction.reset(std::span<const double>(base.valuePtr(), static_cast<std::size_t>(base.nonZeros())));

    // Three rounds of four random breaks each, every round corrected from the intact factor.
    SplitMix64 random(seed);
    Eigen::VectorXd f(base.cols());
    for (Eigen::Index i = 0; i < f.size(); ++i) f[i] = random.uniform(-1.0, 1.0);
    for (int round = 0; round < 3; ++round) {
      for (int n = 0; n < 4; ++n) include[static_cast<std::size_t>(random.uniform(0.0, 1.0) * g.bond_count()) % g.bonds.size()] = 0;
      stiffness.assemble(include, identity);
      const Eigen::SparseMatrix<double> lower = lower_of(stiffness.matrix());
      REQUIRE(correction.update(factor, lower, 1e12));
      CHECK(correction.active());
      const Eigen::VectorXd x = correction.solve(factor, f);
      const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> fresh(stiffness.matrix());
      REQUIRE(fresh.info() == Eigen::Success);
      const Eigen::VectorXd expected = fresh.solve(f);
      CHECK((x - expected).norm() <= 1e-10 * expected.norm());
    }
  }
}

TEST_CASE("capacitance correction: refuses an update dearer than its limit", "[stress][capacitance]") {
  const SupportGraph g = block_wall(9, 8);
  GraphStiffness stiffness(g, Material{});
  std::vector<std::uint8_t> include(g.bonds.size(), 1), identity(g.nodes.size(), 0);
  stiffness.assemble(include, identity);
  const Eigen::SparseMatrix<double> base = lower_of(stiffness.matrix());
  std::vector<int> groups(static_cast<std::size_t>(base.cols()));
  for (std::size_t i = 0; i < groups.size(); ++i) groups[i] = static_cast<int>(i / 6);
  NodeBlockCholesky factor;
  REQUIRE(factor.analyze(base, groups));
  REQUIRE(factor.factorize(base));
  CapacitanceCorrection correction;
  correction.reset(std::span<const double>(base.valuePtr(), static_cast<std::size_t>(base.nonZeros())));
  include[20] = 0;
  stiffness.assemble(include, identity);
  const Eigen::SparseMatrix<double> lower = lower_of(stiffness.matrix());
  CHECK_FALSE(correction.update(factor, lower, 1.0));
  CHECK(correction.update(factor, lower, 1e12));
  CHECK(correction.last_flops() > 1.0);
  CHECK(correction.unknowns() == 12);  // the two nodes of the broken bond
}

TEST_CASE("exact cascade: corrected rounds break the bonds the reference path breaks, round by round",
          "[stress][capacitance][propagation]") {
  struct Wall {
    int nx, nz;
    double strength;
  };
  for (const Wall w : {Wall{23, 22, 2e4}, Wall{23, 22, 3e4}, Wall{30, 20, 2e4}}) {
    const SupportGraph g = block_wall(w.nx, w.nz);
    Material weak;
    weak.tensile_strength = w.strength;
    // The bonds of the block of the second row nearest the middle.
    int hole = 0;
    double best = 1e300;
    for (int v = 0; v < g.node_count(); ++v) {
      const Vec3& c = g.nodes[static_cast<std::size_t>(v)].centroid;
      const double d = std::abs(c.x() - 0.25 * w.nx) + std::abs(c.z() - 0.75);
      if (d < best) best = d, hole = v;
    }
    const std::vector<int> broken = g.node_bonds[static_cast<std::size_t>(hole)];
    for (const Criterion criterion : {Criterion::von_mises, Criterion::tresca}) {
      StrengthCriterionSolver solver(g, weak, criterion, SpringSolverSettings{});
      SpringSolverSettings reference;
      reference.reference = true;
      StrengthCriterionSolver checked(g, weak, criterion, reference);
      Result<PropagationResult> fast = propagate(solver, Loads{}, broken);
      Result<PropagationResult> slow = propagate(checked, Loads{}, broken);
      REQUIRE(fast.ok());
      REQUIRE(slow.ok());
      REQUIRE(solver.cascade() != nullptr);
      CHECK(solver.cascade()->corrected_rounds() > 0);  // the correction is in play
      CHECK(fast->break_order == slow->break_order);
      CHECK(fast->result.falling_clusters == slow->result.falling_clusters);
      CHECK(fast->report.residual < 1e-11);
    }
  }
}
