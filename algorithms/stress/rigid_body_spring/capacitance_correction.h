#pragma once
/// Solves with a stiffness block that differs from the factorised one on a few nodes, through the
/// factor that is there: K = K_B - P E P^T, K_B = L L^T the factorised block, P the unknowns of the
/// nodes whose entries changed, E = P^T (K_B - K) P (dense, #changed unknowns square).
///
/// Design note: a cascade round removes the springs of the bonds it broke (and puts identity rows on
/// the nodes that fall), so K changes only in the columns of a few nodes, while a refactorisation
/// recomputes every row above them in the elimination tree, the top separators included (about half
/// a factorisation on a wall). With s = P^T u, K u = f reads (I - G E) s = P^T K_B^-1 f, G =
/// P^T K_B^-1 P, and then u = K_B^-1 (f + P E s) (Woodbury's identity in its capacitance form, which
/// needs no inverse of E: a broken spring makes E singular). G comes from the columns of L^-1 P, each
/// nonzero only on the elimination-tree path from its node to the root
/// (NodeBlockCholesky::inverse_factor_columns), so a node costs its path's share of L, and a solve
/// costs two triangular solves with L and a dense solve with the capacitance I - G E. A node stays
/// in P (its columns kept) until the next refactorisation, so a round pays only for its new nodes and
/// the dense factorisation of the capacitance, which grows as the cube of their count; an update
/// estimated dearer than the caller's limit is refused, and the caller refactorises instead
/// (cascade_solver.h).

#include "algorithms/core/node_block_cholesky.h"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <span>
#include <vector>

namespace shatter {

class CapacitanceCorrection {
 public:
  /// Takes `base` (the values of the factorised lower triangle, in its pattern) as K_B and forgets
  /// every node: the factor has just been computed from these values.
  void reset(std::span<const double> base);
  /// Forgets the base: the next round must refactorise.
  void clear();
  /// True when a base is held.
  [[nodiscard]] bool has_base() const { return has_base_; }
  /// Brings the correction to the values of `lower` (the factor's pattern, lower triangle, g unknowns
  /// per node as in `factor`): every node with an entry that differs from the base goes into P.
  /// False, and nothing usable, when the update would take more than `max_flops` (its estimate, see
  /// last_flops), P would hold more than kMaxUnknowns unknowns, or the capacitance is numerically
  /// singular (reciprocal condition below 1e-12): refactorise then.
  bool update(const NodeBlockCholesky& factor, const Eigen::SparseMatrix<double>& lower, double max_flops);
  /// The estimated flops of the last update: the new nodes' columns of L^-1 P, G's new blocks and the
  /// capacitance's LU.
  [[nodiscard]] double last_flops() const { return last_flops_; }
  /// The most unknowns P may hold (the capacitance is dense).
  static constexpr int kMaxUnknowns = 600;
  /// True when some node differs from the base (otherwise a solve is the factor's own).
  [[nodiscard]] bool active() const { return !nodes_.empty(); }
  /// Unknowns in P.
  [[nodiscard]] int unknowns() const { return static_cast<int>(g_.rows()); }
  /// x = K^-1 b for the K of the last successful update (#unknowns of the block).
  [[nodiscard]] Eigen::VectorXd solve(const NodeBlockCholesky& factor, const Eigen::VectorXd& b) const;

 private:
  bool has_base_ = false;
  double last_flops_ = 0.0;
  std::vector<double> base_;                  // K_B's values, lower's value order
  int size_ = 0;                              // g, unknowns per node
  std::vector<int> nodes_;                    // the nodes in P, in the order they came
  std::vector<int> slot_;                     // node -> index in nodes_, -1 when not in P
  std::vector<std::vector<int>> paths_;       // per node in P: its path (elimination positions)
  std::vector<std::vector<double>> columns_;  // per node in P: L^-1 P on its path, g x g blocks
  Eigen::MatrixXd g_;                         // G = P^T K_B^-1 P
  Eigen::SparseMatrix<double> e_;             // E = P^T (K_B - K) P
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;  // I - G E
  // K_B^-1 b for the last b solved (the loads, in every round of a cascade), until the base changes.
  mutable bool has_z_ = false;
  mutable Eigen::VectorXd z_rhs_, z_;
};

}  // namespace shatter
