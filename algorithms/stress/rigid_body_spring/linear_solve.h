#pragma once
/// The linear solve K u = f of one anchored component: split into decoupled blocks, each block solved
/// by sparse Cholesky (sparse_cholesky.h: node blocks, or CHOLMOD's supernodes for large factors) when
/// its factorisation is cheap enough, else by Jacobi-preconditioned CG.
/// The split and the factors of the last few K a solver solved are kept in its memory
/// (solved_systems.h): the same K under other loads (a structure evaluated again) only pays the
/// triangular solves.

#include "algorithms/stress/rigid_body_spring/solved_systems.h"
#include "algorithms/stress/stress_model.h"

#include <Eigen/SparseCore>

namespace shatter {

/// Solver options. The direct solve is exact to round-off (the beam tests need 1e-9); it is chosen per
/// decoupled block when its analysis predicts at most `direct_max_flops` for the factorisation:
/// on the 71 x 71 wall's in-plane half (14,910 unknowns) that is 9.4e7 flops, ~9 ms here. Larger
/// blocks (3D bodies fill far more) go to CG. See docs/stress.md, section 3.
struct SpringSolverSettings {
  double direct_max_flops = 1e9;      ///< sparse Cholesky up to this many factorisation flops per block, CG above
  int refinement_steps = 2;           ///< at most this many refinement steps against the full K after a direct solve
  double refinement_gain = 4.0;       ///< refinement stops once a step cut the residual norm by less than this factor
  double cg_tolerance = 1e-10;        ///< relative residual |K_b u_b - f_b| / |f_b| at which CG stops, per block
  int cg_max_iterations = 20000;      ///< CG gives up (converged = false) after this many iterations
  double decoupling_tolerance = 1e-13;///< |K_ij| <= this sqrt(K_ii K_jj) is dropped to find decoupled blocks; 0 keeps all
  bool reference = false;             ///< Eigen SimplicialLDLT on the whole K, no splitting (tests, baselines)
  /// A solve is converged only when its relative residual |f - K u| / |f| against the full K is at most
  /// this (or cg_tolerance, when larger: a CG sweep asks for less). The hardest structure of the hazard
  /// battery (bond lengths alternately x1e-4 and x1e4) leaves 2.1e-7, the benchmark walls 1e-12; a
  /// stiffness that overflows or vanishes in double (E = 1e300, 1e-300) leaves about 1.
  double residual_tolerance = 1e-6;
};

/// The relative residual up to which a solve with `settings` is converged (see residual_tolerance).
double solve_tolerance(const SpringSolverSettings& settings);

/// Solves `k` u = `f` (k: both triangles, SPD, compressed). `u` holds the warm start (used by CG;
/// non-finite entries are replaced by zero) and receives the solution. The report carries the residual
/// |f - k u| / |f| against the full `k`, iterations, and convergence. `k` is taken over: it is kept in
/// `memory` with its split and factors for the next solve of the same K, swapped in without a copy (so
/// the caller's matrix is left empty, or unspecified when the reference path or the size bound keeps
/// nothing); its analyses come from `memory` when a pattern was seen before.
SolverReport solve_linear(Eigen::SparseMatrix<double>&& k, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                          const SpringSolverSettings& settings, SolverMemory& memory);

/// Whether another refinement step is worth its solve: the residual norm went from `last` (before the
/// previous step; infinite before the first) to `now`. Refinement in working precision cuts the residual
/// by a roughly constant factor until it reaches its round-off floor, where a step changes it by less
/// than 2 (the benchmark walls: the first step gains 1.4x to 3x, the second nothing, docs/stress.md
/// section 3), so a step that gained less than `refinement_gain` ends the refinement.
bool refinement_pays(double last, double now, const SpringSolverSettings& settings);

}  // namespace shatter
