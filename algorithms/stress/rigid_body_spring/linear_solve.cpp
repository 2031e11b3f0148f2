#include "algorithms/stress/rigid_body_spring/linear_solve.h"

#include "algorithms/stress/rigid_body_spring/analysis_pool.h"
#include "algorithms/stress/rigid_body_spring/bounded_store.h"
#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"
#include "algorithms/stress/rigid_body_spring/sparse_product.h"
#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace shatter {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Vector = Eigen::VectorXd;

/// x(block)
Vector gather(const Vector& x, const std::vector<int>& block) {
  Vector out(static_cast<Eigen::Index>(block.size()));
  for (std::size_t i = 0; i < block.size(); ++i) out[static_cast<Eigen::Index>(i)] = x[block[i]];
  return out;
}

/// The old single-system path: Eigen's simplicial LDL^T with AMD, plus refinement. An independent
/// reference for the tests.
SolverReport solve_reference(const SparseMatrix& k, const Vector& f, Vector& u, const SpringSolverSettings& settings) {
  SolverReport report;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt(k);
  report.converged = ldlt.info() == Eigen::Success;
  if (report.converged) {
    u = ldlt.solve(f);
    for (int step = 0; step < settings.refinement_steps; ++step) u += ldlt.solve(f - k * u);
  }
  return report;
}

/// One decoupled block solved by Jacobi-CG, warm-started from `u`(block).
SolverReport solve_block_cg(const SparseMatrix& k, const std::vector<int>& block, const std::vector<int>& position,
                            const Vector& f, Vector& u, const SpringSolverSettings& settings) {
  SolverReport report;
  const SparseMatrix a = block_matrix(k, block, position, settings.decoupling_tolerance, false);
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg(a);
  cg.setTolerance(settings.cg_tolerance);
  cg.setMaxIterations(settings.cg_max_iterations);
  const Vector x = cg.solveWithGuess(gather(f, block), gather(u, block));
  for (std::size_t i = 0; i < block.size(); ++i) u[block[i]] = x[static_cast<Eigen::Index>(i)];
  report.iterations = static_cast<int>(cg.iterations());
  report.converged = cg.info() == Eigen::Success;
  return report;
}

/// A decoupled block and how it is solved: its factor once analysed and cheap enough, else CG.
struct Block {
  std::vector<int> unknowns;                 // ascending global indices
  std::optional<SparseCholesky> factor;  // set when factorised
  std::optional<FactorPattern> pattern;      // the factor's pattern (for the analysis pool)
  bool analysed = false;                     // factorisation tried (factor empty: CG block)
};

/// Factorises `block` unless done already or too costly (then it stays a CG block). The analysis
/// comes from this thread's pool when the same pattern was analysed before (analysis_pool.h).
void try_factorize(const SparseMatrix& k, const std::vector<int>& position, const SpringSolverSettings& settings,
                   Block& block) {
  if (block.analysed) return;
  block.analysed = true;
  const SparseMatrix lower = block_matrix(k, block.unknowns, position, settings.decoupling_tolerance, true);
  FactorPattern pattern(lower, node_groups(block.unknowns));
  std::optional<SparseCholesky> cholesky = take_analysed(pattern, lower);
  if (!cholesky) return;
  if (cholesky->factor_flops() > settings.direct_max_flops) {  // a CG block: keep only its analysis
    keep_analysed(std::move(pattern), std::move(*cholesky));
    return;
  }
  if (!cholesky->factorize(lower)) return;  // not kept: its numeric state is partial
  block.factor = std::move(cholesky);
  block.pattern = std::move(pattern);
}

/// u(block) += the factor's solution for r(block).
void add_direct_solution(const Block& block, const Vector& r, Vector& u) {
  const Vector x = block.factor->solve(gather(r, block.unknowns));
  for (std::size_t i = 0; i < block.unknowns.size(); ++i) u[block.unknowns[i]] += x[static_cast<Eigen::Index>(i)];
}

/// A system solved before on this thread: K exactly (pattern and values), the settings that shaped
/// its split, and its blocks with their factors. Solving with the same K again (the same structure
/// under other loads) needs neither the split nor a factorisation: the factors are those the same K
/// would give again, so the solution is bit for bit that of a fresh solve.
struct SolvedSystem {
  std::unique_ptr<SparseMatrix> k;  // compressed; on the heap, as Eigen's SparseMatrix has no move constructor
  double decoupling_tolerance = 0.0, direct_max_flops = 0.0;
  std::vector<Block> blocks;
  std::size_t bytes = 0;
};

constexpr std::size_t kMaxSolvedSystems = 4;

BoundedStore<SolvedSystem>& solved_systems() {
  thread_local BoundedStore<SolvedSystem> systems(kMaxSolvedSystems, kMaxPooledBytes);
  return systems;
}

bool same_pattern(const SolvedSystem& e, const SparseMatrix& k, const SpringSolverSettings& settings) {
  const SparseMatrix& kept = *e.k;
  return kept.cols() == k.cols() && kept.nonZeros() == k.nonZeros() &&
         e.decoupling_tolerance == settings.decoupling_tolerance && e.direct_max_flops == settings.direct_max_flops &&
         std::equal(kept.outerIndexPtr(), kept.outerIndexPtr() + kept.cols() + 1, k.outerIndexPtr()) &&
         std::equal(kept.innerIndexPtr(), kept.innerIndexPtr() + kept.nonZeros(), k.innerIndexPtr());
}

/// Hands a block's factor to the analysis pool (its analysis stays useful for the same pattern).
void pool_factor(Block& block) {
  if (block.factor) keep_analysed(std::move(*block.pattern), std::move(*block.factor));
  block.factor.reset();
}

/// The blocks of `k` as solved before (moved out of the store), or none. A stored system with K's
/// pattern but other values (the same structure, other stiffness) is dropped and its factors go to
/// the analysis pool, where this solve's factorisations find their analyses.
std::optional<std::vector<Block>> take_solved_blocks(const SparseMatrix& k, const SpringSolverSettings& settings) {
  BoundedStore<SolvedSystem>& store = solved_systems();
  std::optional<SolvedSystem> found = store.take([&](const SolvedSystem& e) { return same_pattern(e, k, settings); });
  if (!found) return std::nullopt;
  if (std::equal(found->k->valuePtr(), found->k->valuePtr() + found->k->nonZeros(), k.valuePtr())) {
    ++store.reuses;
    return std::move(found->blocks);
  }
  for (Block& block : found->blocks) pool_factor(block);
  return std::nullopt;
}

/// Stores `blocks`, solved with `k` (swapped in, not copied: `k` is left empty); the oldest systems leave
/// (their factors to the analysis pool) while the store holds kMaxSolvedSystems or would pass
/// kMaxPooledBytes.
void keep_solved_blocks(SparseMatrix& k, const SpringSolverSettings& settings, std::vector<Block> blocks) {
  std::size_t bytes = static_cast<std::size_t>(k.nonZeros()) * (sizeof(double) + sizeof(int));
  for (const Block& block : blocks) bytes += block.factor ? block.factor->factor_bytes() : 0;
  if (bytes > kMaxPooledBytes) {
    for (Block& block : blocks) pool_factor(block);
    return;
  }
  SolvedSystem e;
  e.k = std::make_unique<SparseMatrix>();
  e.k->swap(k);
  e.decoupling_tolerance = settings.decoupling_tolerance;
  e.direct_max_flops = settings.direct_max_flops;
  e.blocks = std::move(blocks);
  e.bytes = bytes;
  solved_systems().keep(std::move(e), [](SolvedSystem& dropped) {
    for (Block& block : dropped.blocks) pool_factor(block);
  });
}

/// Each loaded block is solved on its own (direct, or CG when its factorisation is too costly); a
/// block with no load starts at u = 0, exact but for the dropped couplings. Refinement against the
/// full K then corrects every direct block, factorising an unloaded one only if its residual is above
/// the round-off of f itself (machine epsilon |f|): the in-plane half of a wall leaves ~1e-19 |f| on
/// the out-of-plane half, never factorised, while an axis-aligned cantilever leaves 1e-14 |f| on its
/// axial unknowns, whose correction keeps the axial force at ~1e-26 N rather than 1e-11 N. A K solved
/// before on this thread brings its blocks and factors along (SolvedSystem).
SolverReport solve_blocks(const SparseMatrix& k, const Vector& f, Vector& u, const SpringSolverSettings& settings,
                          std::optional<double>& residual_norm, std::vector<Block>& blocks) {
  SolverReport report;
  if (std::optional<std::vector<Block>> solved = take_solved_blocks(k, settings)) {
    blocks = std::move(*solved);
  } else {
    for (std::vector<int>& unknowns : decoupled_blocks(k, settings.decoupling_tolerance))
      blocks.push_back(Block{std::move(unknowns), std::nullopt, std::nullopt, false});
  }
  std::vector<int> position(static_cast<std::size_t>(k.cols()), -1);
  for (const Block& block : blocks)
    for (std::size_t i = 0; i < block.unknowns.size(); ++i)
      position[static_cast<std::size_t>(block.unknowns[i])] = static_cast<int>(i);
  const double negligible = std::numeric_limits<double>::epsilon() * f.norm();
  for (Block& block : blocks) {
    if (gather(f, block.unknowns).squaredNorm() == 0.0) {
      for (const int i : block.unknowns) u[i] = 0.0;
      continue;
    }
    try_factorize(k, position, settings, block);
    if (block.factor) {
      for (const int i : block.unknowns) u[i] = 0.0;
      add_direct_solution(block, f, u);
    } else {
      const SolverReport r = solve_block_cg(k, block.unknowns, position, f, u, settings);
      report.iterations += r.iterations;
      report.converged = report.converged && r.converged;
    }
  }
  double last = std::numeric_limits<double>::infinity();
  for (int step = 0; step < settings.refinement_steps; ++step) {
    const Vector r = sparse_residual(k, f, u);
    const double now = r.norm();
    if (!refinement_pays(last, now, settings)) {
      residual_norm = now;  // the residual of the final u
      break;
    }
    last = now;
    for (Block& block : blocks) {
      if (gather(r, block.unknowns).norm() <= negligible) continue;
      try_factorize(k, position, settings, block);
      if (block.factor) add_direct_solution(block, r, u);
    }
  }
  return report;
}

}  // namespace

double solve_tolerance(const SpringSolverSettings& settings) {
  return std::max(settings.residual_tolerance, settings.cg_tolerance);
}

bool refinement_pays(double last, double now, const SpringSolverSettings& settings) {
  return now > 0.0 && now * settings.refinement_gain <= last;
}

void forget_solver_reuse() {
  solved_systems().clear();
  forget_analysed();
}

std::size_t solved_system_reuses() { return solved_systems().reuses; }

SolverReport solve_linear(SparseMatrix&& k, const Vector& f, Vector& u, const SpringSolverSettings& settings) {
  if (!u.allFinite()) u.setZero();
  SolverReport report;
  std::optional<double> residual_norm;  // set by a refinement that ended with it
  std::vector<Block> blocks;            // of the block path, kept with K for reuse
  if (settings.reference) {
    report = solve_reference(k, f, u, settings);
  } else {
    report = solve_blocks(k, f, u, settings, residual_norm, blocks);
  }
  if (!u.allFinite()) {
    report.converged = false;
    u.setZero();
  }
  const double f_norm = f.norm();
  if (!residual_norm || !report.converged) residual_norm = (f - sparse_product(k, u)).norm();
  report.residual = f_norm > 0.0 ? *residual_norm / f_norm : 0.0;
  judge_convergence(report, solve_tolerance(settings));
  if (!settings.reference) keep_solved_blocks(k, settings, std::move(blocks));
  return report;
}

}  // namespace shatter
