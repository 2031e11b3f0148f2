#pragma once
/// The systems K u = f one solver solved before, kept with their split into decoupled blocks and their
/// factors, keyed by K itself.
///
/// Design note: K does not depend on the loads, so the same structure under new loads (every impact,
/// every change of a carried load) needs neither the split nor a factorisation: the factors are those
/// the same K would give again, so the solution is bit for bit that of a fresh solve. K is compared
/// exactly (pattern and values, O(nnz)), never by a hash alone. A kept system with K's pattern but other
/// values (the same structure, another stiffness) is dropped and its factors go to the analysis pool
/// (analysis_pool.h), where the new factorisations find their analyses. The store belongs to one solver
/// (StrengthCriterionSolver: one structure): two solvers never see each other's systems. Bounded at
/// kMaxSolvedSystems systems and kMaxPooledBytes; the oldest leave first, their factors to the pool.

#include "algorithms/stress/rigid_body_spring/analysis_pool.h"
#include "algorithms/stress/rigid_body_spring/bounded_store.h"
#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <Eigen/SparseCore>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace shatter {

struct SpringSolverSettings;

/// Systems kept per solver.
inline constexpr std::size_t kMaxSolvedSystems = 4;

/// A decoupled block of K and how it is solved: its factor once analysed and cheap enough, else CG.
struct SolvedBlock {
  std::vector<int> unknowns;             ///< ascending indices into K
  std::optional<SparseCholesky> factor;  ///< set when factorised
  std::optional<FactorPattern> pattern;  ///< the factor's pattern (for the analysis pool)
  bool analysed = false;                 ///< factorisation tried (factor empty: a CG block)
};

/// The systems one solver solved before (see the design note above).
class SolvedSystems {
 public:
  /// The blocks of `k` as solved before (moved out of the store), or none. A kept system with k's
  /// pattern and the same split settings but other values is dropped, its factors to `pool`.
  std::optional<std::vector<SolvedBlock>> take(const Eigen::SparseMatrix<double>& k, const SpringSolverSettings& settings,
                                               AnalysisPool& pool);
  /// Keeps `blocks`, solved with `k` (swapped in, not copied: `k` is left empty). A system above
  /// kMaxPooledBytes is not kept (its factors go to `pool`), nor are the oldest ones it pushes out.
  void keep(Eigen::SparseMatrix<double>& k, const SpringSolverSettings& settings, std::vector<SolvedBlock> blocks,
            AnalysisPool& pool);
  /// Solves that found their K kept (tests).
  [[nodiscard]] std::size_t reuses() const { return store_.reuses; }

 private:
  struct System {
    std::unique_ptr<Eigen::SparseMatrix<double>> k;  // on the heap: Eigen's SparseMatrix has no move constructor
    double decoupling_tolerance = 0.0, direct_max_flops = 0.0;
    std::vector<SolvedBlock> blocks;
    std::size_t bytes = 0;
  };
  BoundedStore<System> store_{kMaxSolvedSystems, kMaxPooledBytes};
};

/// What one solver keeps between its solves: analysed factors by pattern and whole solved systems.
struct SolverMemory {
  AnalysisPool analyses;   ///< analysed factors by exact pattern
  SolvedSystems systems;   ///< systems solved before, by exact K
};

}  // namespace shatter
