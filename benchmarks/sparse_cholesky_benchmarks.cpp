// The two sparse Cholesky factorisations of a stiffness block side by side: node blocks
// (node_block_cholesky.h) and CHOLMOD's supernodes (supernodal_cholesky.h), on the in-plane half of
// walls of n x n blocks (the decoupled block the wall benchmarks factorise), for the analysis, the
// numeric factorisation and one solve; and the residual after each refinement step of a solve. These
// are the figures of docs/stress.md, section 3 ("Node blocks"). The main is in fracture_benchmarks.cpp.
#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "algorithms/stress/rigid_body_spring/node_block_cholesky.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/rigid_body_spring/supernodal_cholesky.h"
#include "tests/stress/structures.h"

#include <benchmark/benchmark.h>

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
    const SupportGraph g = test::block_wall(side, side);
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

template <class Factor>
void cholesky_factorize(benchmark::State& state) {
  const WallBlock& w = wall_block(static_cast<int>(state.range(0)));
  Factor factor;
  prepare(state, w, factor);
  for (auto _ : state) benchmark::DoNotOptimize(factor.factorize(w.lower));
  add_counters(state, w, factor);
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
BENCHMARK_TEMPLATE(cholesky_solve, NodeBlockCholesky)->Apply(wall_sides);
BENCHMARK_TEMPLATE(cholesky_solve, SupernodalCholesky)->Apply(wall_sides);
BENCHMARK(refinement_residuals)->Arg(8)->Arg(23)->Arg(50)->Arg(71)->Unit(benchmark::kMillisecond);
