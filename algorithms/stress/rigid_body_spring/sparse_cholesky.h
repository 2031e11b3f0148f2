#pragma once
/// The sparse Cholesky factorisation of a stiffness block, by node blocks or by CHOLMOD's supernodes,
/// chosen by the analysis.
///
/// Design note: both orders the nodes by the same AMD (node_ordering.h). Node blocks
/// (node_block_cholesky.h) run every step as a fixed-size block operation and analyse on the node
/// graph; CHOLMOD's supernodal factorisation (supernodal_cholesky.h) runs dense BLAS on wide
/// supernodes. The first wins while the factorisation is small (its fixed costs dominate), the second
/// once the top separators are wide enough for BLAS; the switch is at kNodeBlockMaxFlops, measured on
/// the benchmark walls (docs/stress.md, section 3). Nodes of mixed sizes always go to CHOLMOD.

#include "algorithms/core/node_block_cholesky.h"
#include "algorithms/stress/rigid_body_spring/supernodal_cholesky.h"

#include <Eigen/SparseCore>

#include <span>
#include <variant>

namespace shatter {

/// Factorisations up to this many flops (as CHOLMOD counts them) go by node blocks.
inline constexpr double kNodeBlockMaxFlops = 1e8;

class SparseCholesky {
 public:
  /// Orders and analyses `lower` (the lower triangle of K, compressed columns, square); `groups` as for
  /// SupernodalCholesky::analyze. False if the analysis fails.
  bool analyze(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups = {});
  /// Floating-point operations of the numeric factorisation (CHOLMOD's count).
  [[nodiscard]] double factor_flops() const;
  /// Bytes the factor takes once factorised.
  [[nodiscard]] std::size_t factor_bytes() const;
  /// Factorises `lower`, whose pattern must be the analysed one. False if K is not positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  /// Solves K x = b with the current factor.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// True when factorised by node blocks (tests, docs).
  [[nodiscard]] bool by_node_blocks() const { return std::holds_alternative<NodeBlockCholesky>(impl_); }
  /// The node-block factor, or null when factorised by CHOLMOD or not analysed.
  [[nodiscard]] const NodeBlockCholesky* node_blocks() const { return std::get_if<NodeBlockCholesky>(&impl_); }

 private:
  std::variant<std::monostate, NodeBlockCholesky, SupernodalCholesky> impl_;
};

}  // namespace shatter
