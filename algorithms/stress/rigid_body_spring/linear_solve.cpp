#include "algorithms/stress/rigid_body_spring/linear_solve.h"

#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"
#include "algorithms/stress/rigid_body_spring/sparse_product.h"
#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

namespace shatter {

namespace {

/// Refinement steps with the residual in long double, at most, for a solve that missed its tolerance.
constexpr int kExtendedSteps = 4;

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

/// Factorises `block` unless done already or too costly (then it stays a CG block). The analysis
/// comes from `pool` when the same pattern was analysed before (analysis_pool.h).
void try_factorize(const SparseMatrix& k, const std::vector<int>& position, const SpringSolverSettings& settings,
                   AnalysisPool& pool, SolvedBlock& block) {
  if (block.analysed) return;
  block.analysed = true;
  const SparseMatrix lower = block_matrix(k, block.unknowns, position, settings.decoupling_tolerance, true);
  FactorPattern pattern(lower, node_groups(block.unknowns));
  std::optional<SparseCholesky> cholesky = pool.take(pattern, lower);
  if (!cholesky) return;
  if (cholesky->factor_flops() > settings.direct_max_flops) {  // a CG block: keep only its analysis
    pool.keep(std::move(pattern), std::move(*cholesky));
    return;
  }
  if (!cholesky->factorize(lower)) return;  // not kept: its numeric state is partial
  block.factor = std::move(cholesky);
  block.pattern = std::move(pattern);
}

/// u(block) += the factor's solution for r(block).
void add_direct_solution(const SolvedBlock& block, const Vector& r, Vector& u) {
  const Vector x = block.factor->solve(gather(r, block.unknowns));
  for (std::size_t i = 0; i < block.unknowns.size(); ++i) u[block.unknowns[i]] += x[static_cast<Eigen::Index>(i)];
}

/// Each loaded block is solved on its own (direct, or CG when its factorisation is too costly); a
/// block with no load starts at u = 0, exact but for the dropped couplings. Refinement against the
/// full K then corrects every direct block, factorising an unloaded one only if its residual is above
/// the round-off of f itself (machine epsilon |f|): the in-plane half of a wall leaves ~1e-19 |f| on
/// the out-of-plane half, never factorised, while an axis-aligned cantilever leaves 1e-14 |f| on its
/// axial unknowns, whose correction keeps the axial force at ~1e-26 N rather than 1e-11 N. A K the
/// solver solved before brings its blocks and factors along (solved_systems.h).
SolverReport solve_blocks(const SparseMatrix& k, const Vector& f, Vector& u, const SpringSolverSettings& settings,
                          SolverMemory& memory, std::optional<double>& residual_norm, std::vector<SolvedBlock>& blocks) {
  SolverReport report;
  if (std::optional<std::vector<SolvedBlock>> solved = memory.systems.take(k, settings, memory.analyses)) {
    blocks = std::move(*solved);
  } else {
    for (std::vector<int>& unknowns : decoupled_blocks(k, settings.decoupling_tolerance))
      blocks.push_back(SolvedBlock{std::move(unknowns), std::nullopt, std::nullopt, false});
  }
  std::vector<int> position(static_cast<std::size_t>(k.cols()), -1);
  for (const SolvedBlock& block : blocks)
    for (std::size_t i = 0; i < block.unknowns.size(); ++i)
      position[static_cast<std::size_t>(block.unknowns[i])] = static_cast<int>(i);
  const double negligible = std::numeric_limits<double>::epsilon() * f.norm();
  for (SolvedBlock& block : blocks) {
    if (gather(f, block.unknowns).squaredNorm() == 0.0) {
      for (const int i : block.unknowns) u[i] = 0.0;
      continue;
    }
    try_factorize(k, position, settings, memory.analyses, block);
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
    for (SolvedBlock& block : blocks) {
      if (gather(r, block.unknowns).norm() <= negligible) continue;
      try_factorize(k, position, settings, memory.analyses, block);
      if (block.factor) add_direct_solution(block, r, u);
    }
  }
  // Near a mechanism (a piece held by a sliver of a bond) the displacements are large and K u cancels f
  // to within double's round-off of |K| |u|: the residual formed in double, and refinement from it,
  // stall above the tolerance where u itself may be within it. A solve that missed its tolerance is
  // refined further with residuals accumulated in long double (extended_residual), while each step
  // lowers that residual (at most kExtendedSteps), and reports the residual of the u it keeps. A solve
  // within its tolerance never comes here: its u and residual are as before, bit for bit.
  if (!report.converged || !u.allFinite()) return report;
  const double f_norm = f.norm();
  if (!residual_norm) residual_norm = (f - sparse_product(k, u)).norm();  // as solve_linear forms it
  const double within = solve_tolerance(settings) * f_norm;  // the largest residual norm converged
  if (!(f_norm > 0.0) || *residual_norm <= within) return report;
  ExtendedResidual best = extended_residual(k, f, u);
  for (int step = 0; step < kExtendedSteps && best.norm > within; ++step) {
    Vector trial = u;
    for (SolvedBlock& block : blocks) {
      if (gather(best.r, block.unknowns).norm() <= negligible) continue;
      try_factorize(k, position, settings, memory.analyses, block);
      if (block.factor) add_direct_solution(block, best.r, trial);
    }
    ExtendedResidual next = extended_residual(k, f, trial);
    if (!(next.norm < best.norm)) break;
    u = std::move(trial);
    best = std::move(next);
  }
  residual_norm = best.norm;
  return report;
}

}  // namespace

double solve_tolerance(const SpringSolverSettings& settings) {
  return std::max(settings.residual_tolerance, settings.cg_tolerance);
}

bool refinement_pays(double last, double now, const SpringSolverSettings& settings) {
  return now > 0.0 && now * settings.refinement_gain <= last;
}

SolverReport solve_linear(SparseMatrix&& k, const Vector& f, Vector& u, const SpringSolverSettings& settings,
                          SolverMemory& memory) {
  if (!u.allFinite()) u.setZero();
  SolverReport report;
  std::optional<double> residual_norm;  // set by a refinement that ended with it
  std::vector<SolvedBlock> blocks;      // of the block path, kept with K for reuse
  if (settings.reference) {
    report = solve_reference(k, f, u, settings);
  } else {
    report = solve_blocks(k, f, u, settings, memory, residual_norm, blocks);
  }
  if (!u.allFinite()) {
    report.converged = false;
    u.setZero();
  }
  const double f_norm = f.norm();
  if (!residual_norm || !report.converged) residual_norm = (f - sparse_product(k, u)).norm();
  report.residual = f_norm > 0.0 ? *residual_norm / f_norm : 0.0;
  judge_convergence(report, solve_tolerance(settings));
  if (!settings.reference) memory.systems.keep(k, settings, std::move(blocks), memory.analyses);
  return report;
}

}  // namespace shatter
