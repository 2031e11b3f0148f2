// The two sparse Cholesky factorisations of a stiffness block side by side: node blocks
// (node_block_cholesky.h) and CHOLMOD's supernodes (supernodal_cholesky.h), on the in-plane half of
// walls of n x n blocks (the decoupled block the wall benchmarks factorise), for the analysis, the
// numeric factorisation and one solve; the node blocks' refactorisation after a cascade's break; and
// the residual after each refinement step of a solve. These are the figures of docs/stress.md,
// section 3 ("Node blocks", "Partial refactorisation"). The main is in benchmark_main.cpp.
#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "algorithms/core/node_block_cholesky.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/rigid_body_spring/supernodal_cholesky.h"
#include "fixtures/structures.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace shatter;

/// The wall's K, its loads, and the lower triangle of its in-plane block with the node groups.
struct WallBlock {
  Eigen::SparseMatrix<double> k;
  Eigen::VectorXd f;
  std::vector<int> unknowns;
  Eigen::SparseMatrix<double> lower;
  std::vector<int> groups;
};

const WallBlock& wall_block(int side) {
  static std::map<int, std::unique_ptr<WallBlock>> cache;
  auto& slot = cache[side];
  if (!slot) {
    const SupportGraph g = fixtures::block_wall(side, side);
    GraphStiffness stiffness(g, Material{});
    const std::vector<std::uint8_t> all(g.bonds.size(), 1), none(g.nodes.size(), 0);
    stiffness.assemble(all, none);
    slot = std::make_unique<WallBlock>();
    slot->k = stiffness.matrix();
    const std::vector<double> loads = node_loads(g, Loads{}, Material{});
    slot->f = Eigen::VectorXd::Zero(slot->k.cols());
    for (int v = 0; v < g.node_count(); ++v)
      if (const int i = stiffness.first_unknown(v); i >= 0)
        for (int q = 0; q < 6; ++q) slot->f[i + q] = loads[6 * static_cast<std::size_t>(v) + static_cast<std::size_t>(q)];
    // The loaded block: the one holding the first node's u_x (gravity is in the wall's plane).
    for (std::vector<int>& block : decoupled_blocks(slot->k, SpringSolverSettings{}.decoupling_tolerance))
      if (block.front() == 0) slot->unknowns = std::move(block);
    std::vector<int> position(static_cast<std::size_t>(slot->k.cols()), -1);
    for (std::size_t i = 0; i < slot->unknowns.size(); ++i) position[static_cast<std::size_t>(slot->unknowns[i])] = static_cast<int>(i);
    slot->lower = block_matrix(slot->k, slot->unknowns, position, SpringSolverSettings{}.decoupling_tolerance, true);
    slot->groups = node_groups(slot->unknowns);
  }
  return *slot;
}

template <class Factor>
void add_counters(benchmark::State& state, const WallBlock& w, const Factor& factor) {
  state.counters["unknowns"] = static_cast<double>(w.lower.cols());
  state.counters["flops"] = factor.factor_flops();
}

template <class Factor>
void cholesky_analyze(benchmark::State& state) {
  const WallBlock& w = wall_block(static_cast<int>(state.range(0)));
  Factor factor;
  for (auto _ : state) benchmark::DoNotOptimize(factor.analyze(w.lower, w.groups));
  add_counters(state, w, factor);
}

/// `factor` analysed and factorised for `w`'s block; the benchmark is marked failed otherwise.
template <class Factor>
void prepare(benchmark::State& state, const WallBlock& w, Factor& factor) {
  if (!factor.analyze(w.lower, w.groups) || !factor.factorize(w.lower)) state.SkipWithError("factorisation failed");
}

/// A factorisation of values that all changed: K and 2 K by turns (node blocks keep the rows whose
/// values did not change, cholesky_refactorize).
template <class Factor>
void cholesky_factorize(benchmark::State& state) {
  const WallBlock& w = wall_block(static_cast<int>(state.range(0)));
  Factor factor;
  prepare(state, w, factor);
  const Eigen::SparseMatrix<double> doubled = 2.0 * w.lower;
  bool turn = false;
  for (auto _ : state) {
    benchmark::DoNotOptimize(factor.factorize(turn ? w.lower : doubled));
    turn = !turn;
  }
  add_counters(state, w, factor);
}

/// A cascade's refactorisation: by turns, the intact block and the block with the bonds of one block
/// of the second row near the middle broken (that node an identity row), in the intact pattern. Node
/// blocks recompute the changed rows and their elimination-tree ancestors only: counter `rows` of
/// `nodes`.
void cholesky_refactorize(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const WallBlock& w = wall_block(side);
  const SupportGraph g = fixtures::block_wall(side, side);
  int hole = 0;
  double best = 1e300, x_mid = 0.0;
  for (const SupportNode& n : g.nodes) x_mid = std::max(x_mid, n.centroid.x());
  for (int v = 0; v < g.node_count(); ++v) {
    const Vec3& c = g.nodes[static_cast<std::size_t>(v)].centroid;
    const double d = std::abs(c.x() - x_mid / 2) + std::abs(c.z() - 0.75);
    if (d < best) best = d, hole = v;
  }
  GraphStiffness stiffness(g, Material{});
  std::vector<std::uint8_t> include(g.bonds.size(), 1), identity(g.nodes.size(), 0);
  for (const int b : g.node_bonds[static_cast<std::size_t>(hole)]) include[static_cast<std::size_t>(b)] = 0;
  identity[static_cast<std::size_t>(hole)] = 1;
  stiffness.assemble(include, identity);
  Eigen::SparseMatrix<double> broken = w.lower;  // same pattern, the broken K's values
  for (int c = 0; c < broken.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(broken, c); it; ++it)
      it.valueRef() = stiffness.matrix().coeff(w.unknowns[static_cast<std::size_t>(it.row())],
                                               w.unknowns[static_cast<std::size_t>(it.col())]);
  NodeBlockCholesky factor;
  prepare(state, w, factor);
  bool turn = false;
  int rows = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(factor.factorize(turn ? w.lower : broken));
    rows = factor.rows_refactorised();
    turn = !turn;
  }
  add_counters(state, w, factor);
  state.counters["rows"] = rows;
  state.counters["nodes"] = static_cast<double>(w.groups.back() + 1);
}

template <class Factor>
void cholesky_solve(benchmark::State& state) {
  const WallBlock& w = wall_block(static_cast<int>(state.range(0)));
  Factor factor;
  prepare(state, w, factor);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(w.lower.cols());
  for (auto _ : state) benchmark::DoNotOptimize(factor.solve(b));
  add_counters(state, w, factor);
}

/// The residual |f - K u| / |f| (against the whole K) after the direct solve of the in-plane block
/// and after each of three refinement steps, as counters residual_0 .. residual_3.
void refinement_residuals(benchmark::State& state) {
  const WallBlock& w = wall_block(static_cast<int>(state.range(0)));
  NodeBlockCholesky factor;
  prepare(state, w, factor);
  std::vector<double> residuals;
  for (auto _ : state) {
    residuals.clear();
    Eigen::VectorXd u = Eigen::VectorXd::Zero(w.k.cols()), r = w.f;
    for (int step = 0; step < 4; ++step) {
      Eigen::VectorXd rb(static_cast<Eigen::Index>(w.unknowns.size()));
      for (std::size_t i = 0; i < w.unknowns.size(); ++i) rb[static_cast<Eigen::Index>(i)] = r[w.unknowns[i]];
      const Eigen::VectorXd x = factor.solve(rb);
      for (std::size_t i = 0; i < w.unknowns.size(); ++i) u[w.unknowns[i]] += x[static_cast<Eigen::Index>(i)];
      r = w.f - w.k * u;
      residuals.push_back(r.norm() / w.f.norm());
    }
    benchmark::DoNotOptimize(residuals);
  }
  for (std::size_t i = 0; i < residuals.size(); ++i) state.counters["residual_" + std::to_string(i)] = residuals[i];
}

void wall_sides(benchmark::internal::Benchmark* b) {
  for (const int side : {12, 23, 36, 50, 71, 100, 141}) b->Arg(side);
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK_TEMPLATE(cholesky_analyze, NodeBlockCholesky)->Apply(wall_sides);
BENCHMARK_TEMPLATE(cholesky_analyze, SupernodalCholesky)->Apply(wall_sides);
BENCHMARK_TEMPLATE(cholesky_factorize, NodeBlockCholesky)->Apply(wall_sides);
BENCHMARK_TEMPLATE(cholesky_factorize, SupernodalCholesky)->Apply(wall_sides);
BENCHMARK(cholesky_refactorize)->Apply(wall_sides);
BENCHMARK_TEMPLATE(cholesky_solve, NodeBlockCholesky)->Apply(wall_sides);
BENCHMARK_TEMPLATE(cholesky_solve, SupernodalCholesky)->Apply(wall_sides);
BENCHMARK(refinement_residuals)->Arg(8)->Arg(23)->Arg(50)->Arg(71)->Unit(benchmark::kMillisecond);
