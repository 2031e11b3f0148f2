#pragma once
/// Sparse Cholesky K = L L^T in dense node blocks: for a matrix whose unknowns come in nodes of g
/// unknowns each (g from 1 to 6, the same for every node), with the fill and elimination tree of the
/// graph between nodes.
///
/// Design note: a rigid-body-spring stiffness is a graph of nodes (rigid bodies) coupled by dense
/// blocks: 6 x 6 in a 3D body, 3 x 3 in each decoupled half of a planar wall. Factorising it by node
/// blocks makes every step a fixed-size g x g operation that the compiler unrolls, and its symbolic
/// analysis (elimination tree, column counts) runs on the node graph, g^2 times smaller than the
/// scalar pattern. For the small and medium systems of one structure (up to about 1e8 flops,
/// sparse_cholesky.h) that beats CHOLMOD's supernodal factorisation, whose supernodes are then too
/// narrow for BLAS to pay for its per-call overhead, and whose analysis works on the scalar pattern
/// (docs/stress.md, section 3).
/// The factorisation is up-looking (row by row, as Eigen's SimplicialLLT, in blocks): row block k of L
/// solves L(0:k-1, 0:k-1) L(k, 0:k-1)^T = K(0:k-1, k) over the reach of row k in the elimination tree.
/// One object owns its pattern and factor; it is movable and copyable.

#include <Eigen/SparseCore>

#include <span>
#include <vector>

namespace shatter {

class NodeBlockCholesky {
 public:
  /// The largest node size handled.
  static constexpr int kMaxNodeSize = 6;

  /// Orders the nodes of `lower` (the lower triangle of K, compressed columns, square) by AMD on the
  /// node graph and analyses the factor's pattern. `groups` holds one node id per column,
  /// non-decreasing, ids from 0 on (empty: one node per unknown). False when `lower` is empty or not a
  /// lower triangle (an entry above the diagonal between two nodes), the nodes are not all of one size
  /// from 1 to kMaxNodeSize, or AMD fails; the object is then empty.
  bool analyze(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups = {});
  /// Floating-point operations of the numeric factorisation, counted as CHOLMOD counts them: the sum
  /// over the scalar columns of L of the square of their entry counts.
  [[nodiscard]] double factor_flops() const { return flops_; }
  /// Bytes the factor and its pattern take once factorised.
  [[nodiscard]] std::size_t factor_bytes() const;
  /// Factorises `lower`, whose pattern must be the analysed one. False if K is not positive definite
  /// (a diagonal block's Cholesky fails) or a value is not finite.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  /// Solves K x = b with the current factor (NaN everywhere when the last factorisation failed).
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// The nodes in elimination order (AMD on the node graph), empty before analysis.
  [[nodiscard]] std::span<const int> node_order() const { return order_; }

 private:
  void build_gather(const Eigen::SparseMatrix<double>& lower);
  template <int G>
  bool factorize_blocks(const double* values);
  template <int G>
  void solve_blocks(double* x) const;

  bool factorised_ = false;  // the last factorisation succeeded
  int size_ = 0;       // g: unknowns per node
  int nodes_ = 0;      // N
  double flops_ = 0.0;
  std::vector<int> order_;       // elimination position -> node (its unknowns are size_ * node + t)
  std::vector<int> parent_;      // elimination tree over positions, -1 at a root
  std::vector<int> column_start_;// N + 1: first block of each column of L below the diagonal
  // K's blocks by row of the elimination order: row k holds K(k, i) for i <= k (the diagonal last);
  // each block's g x g entries (column-major) as indices into lower's values, -1 where K stores none.
  // The diagonal block gathers its lower triangle only (all its Cholesky reads). gather_ is built by the
  // first factorisation, from the node pairs of lower (v, w > v, by v) and their blocks.
  std::vector<int> row_start_, row_column_, gather_, pairs_, pair_block_;
  // The factor: rows and g x g blocks (column-major) of L below the diagonal, column by column, and
  // the inverses of the diagonal blocks (lower triangular; every use of L(j, j) is a solve with it).
  std::vector<int> rows_;
  std::vector<double> blocks_, diagonal_;
  // Workspace of the factorisation.
  std::vector<double> work_;
  std::vector<int> flag_, stack_, pattern_, fill_;
};

}  // namespace shatter
