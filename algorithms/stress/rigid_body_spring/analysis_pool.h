#pragma once
/// Analysed sparse Cholesky factors (sparse_cholesky.h) kept for reuse, keyed by the exact pattern they were analysed for.
///
/// Design note: the ordering (AMD) and the symbolic factorisation depend only on the pattern of the
/// lower triangle and on the node groups, so a factor analysed for a pattern serves every later
/// matrix with the very same pattern, and its numeric factorisation gives bit for bit what a fresh
/// analysis would. The same structure under new loads reuses its whole factor (the solved systems of
/// linear_solve.h); this pool serves the same pattern with other values (another material, a system
/// dropped from that store) and a cascade run again, whose reused pattern (cascade_solver.h) is that
/// of the intact graph whatever broke. The pool belongs to one solver (StrengthCriterionSolver: one
/// structure), never to a thread or the process, so two solvers never see each other's factors; it
/// is not locked (one solve at a time). A factor is used by one solve at a time: `take` hands it out
/// and removes it, `keep` puts it back. It is bounded (kMaxPooledFactors factors and kMaxPooledBytes
/// of factor storage; the least recently kept goes first), and a pattern is matched by its whole
/// arrays, never by a hash alone.

#include "algorithms/stress/rigid_body_spring/bounded_store.h"
#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <Eigen/SparseCore>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace shatter {

inline constexpr std::size_t kMaxPooledFactors = 8;
/// Bytes kept per solver by this pool, and again by its solved systems (solved_systems.h), so at most
/// 256 MiB per solver in all; a 9,940-bond wall's system and factor take about 40 MiB.
inline constexpr std::size_t kMaxPooledBytes = std::size_t{128} << 20;

/// The exact pattern a factor is analysed for: column starts, row indices and node groups.
struct FactorPattern {
  FactorPattern(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups);
  bool operator==(const FactorPattern&) const = default;
  std::vector<int> outer, inner, groups;
  std::uint64_t hash = 0;
};

/// Analysed factors kept for reuse by their exact pattern (see the design note above).
class AnalysisPool {
 public:
  /// A factor analysed for `pattern` (of `lower`): the pooled one when there is one (removed from the
  /// pool), else analysed now. Empty when the analysis fails.
  std::optional<SparseCholesky> take(const FactorPattern& pattern, const Eigen::SparseMatrix<double>& lower);
  /// Puts `factor`, analysed for `pattern`, into the pool.
  void keep(FactorPattern pattern, SparseCholesky factor);
  /// Pooled factors handed out by take so far (tests).
  [[nodiscard]] std::size_t reuses() const { return store_.reuses; }

 private:
  struct Entry {
    FactorPattern pattern;
    SparseCholesky factor;
    std::size_t bytes = 0;
  };
  BoundedStore<Entry> store_{kMaxPooledFactors, kMaxPooledBytes};
};

}  // namespace shatter
