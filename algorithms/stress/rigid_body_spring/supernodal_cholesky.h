#pragma once
/// Supernodal sparse Cholesky K = L L^T of a symmetric positive definite matrix, by CHOLMOD.
///
/// Design note: Eigen's SimplicialLDLT factorises column by column at well below the machine's flop
/// rate; CHOLMOD's supernodal factorisation groups columns with the same pattern into dense blocks
/// handled by BLAS, 3-4 times faster on the same fill (docs/stress.md, section 3). The analysis (AMD
/// ordering, symbolic factor) is done first and gives the factorisation's flop count, so the caller
/// can choose an iterative solve instead when the fill would be too large (3D bodies) before paying
/// for it. One object owns one CHOLMOD workspace and factor; it is movable, not copyable.

#include <Eigen/SparseCore>

#include <memory>
#include <span>

namespace shatter {

class SupernodalCholesky {
 public:
  SupernodalCholesky();
  ~SupernodalCholesky();
  SupernodalCholesky(SupernodalCholesky&&) noexcept;
  SupernodalCholesky& operator=(SupernodalCholesky&&) noexcept;
  SupernodalCholesky(const SupernodalCholesky&) = delete;
  SupernodalCholesky& operator=(const SupernodalCholesky&) = delete;

  /// Orders and analyses `lower` (the lower triangle of K, compressed columns, square). False if
  /// CHOLMOD fails (out of memory, bad input). `groups` is empty (AMD on the unknowns) or holds one
  /// group id per column, non-decreasing with the column, ids from 0 on: AMD then orders the graph
  /// between groups and each group's columns stay together in their order (the unknowns of one rigid
  /// body couple to the same neighbours; AMD on the node graph costs a fraction of AMD on the
  /// unknowns, docs/stress.md section 3). `order`, when given with groups, is that node order already
  /// computed (node_ordering.h).
  bool analyze(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups = {},
               std::span<const int> order = {});
  /// Floating-point operations the numeric factorisation of the analysed pattern takes.
  [[nodiscard]] double factor_flops() const;
  /// Bytes the factor takes once factorised (values and supernode indices), 0 before analysis.
  [[nodiscard]] std::size_t factor_bytes() const;
  /// Factorises `lower`, whose pattern must be the analysed one. False if K is not positive definite
  /// (to working precision) or CHOLMOD fails.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  /// Solves K x = b with the current factor.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace shatter
