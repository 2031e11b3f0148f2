#pragma once
/// Analysed sparse Cholesky factors (sparse_cholesky.h) kept for reuse, keyed by the exact pattern they were analysed for.
///
/// Design note: the ordering (AMD) and the symbolic factorisation depend only on the pattern of the
/// lower triangle and on the node groups, so a factor analysed for a pattern serves every later
/// matrix with the very same pattern, and its numeric factorisation gives bit for bit what a fresh
/// analysis would. The same structure under new loads reuses its whole factor (the solved systems of
/// linear_solve.h); this pool serves the same pattern with other values (another material, a system
/// dropped from that store) and a cascade run again, whose reused pattern (cascade_solver.h) is that
/// of the intact graph whatever broke. The pool belongs to the calling thread (no locking); a factor is used by one solve
/// at a time: `take_analysed` hands it out and removes it, `keep_analysed` puts it back. It is bounded
/// (kMaxPooledFactors factors and kMaxPooledBytes of factor storage; the least recently kept goes
/// first), and a pattern is matched by its whole arrays, never by a hash alone.

#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <Eigen/SparseCore>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace shatter {

inline constexpr std::size_t kMaxPooledFactors = 8;
/// Bytes kept per thread by this pool, and again by the solved systems of linear_solve.h (so at most
/// 256 MiB per thread in all); a 9,940-bond wall's system and factor take about 40 MiB.
inline constexpr std::size_t kMaxPooledBytes = std::size_t{128} << 20;

/// The exact pattern a factor is analysed for: column starts, row indices and node groups.
struct FactorPattern {
  FactorPattern(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups);
  bool operator==(const FactorPattern&) const = default;
  std::vector<int> outer, inner, groups;
  std::uint64_t hash = 0;
};

/// A factor analysed for `pattern` (of `lower`): this thread's pooled one when there is one, else
/// analysed now. Empty when the analysis fails.
std::optional<SparseCholesky> take_analysed(const FactorPattern& pattern, const Eigen::SparseMatrix<double>& lower);

/// Puts `factor`, analysed for `pattern`, into this thread's pool.
void keep_analysed(FactorPattern pattern, SparseCholesky factor);

/// Empties this thread's pool (benchmarks of cold solves, tests).
void forget_analysed();

/// Pooled factors handed out by take_analysed on this thread so far (tests).
std::size_t analysed_reuses();

}  // namespace shatter
