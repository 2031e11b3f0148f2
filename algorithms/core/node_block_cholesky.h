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
/// Row k therefore depends only on row k of K and on the rows of its descendants in that tree, so a
/// factorisation of new values after a successful one recomputes only the rows whose values of K
/// changed and their ancestors; every other row is kept. The kept rows are the ones a
/// factorisation from scratch would compute, bit for bit, and so is the whole factor. That is what a
/// cascade of breaking bonds needs: each round changes the blocks of a few nodes (docs/stress.md,
/// section 3).
/// One object owns its pattern and factor; it is movable and copyable (a moved-from object refuses to
/// factorise and solves to NaN until analysed again).

#include <Eigen/SparseCore>

#include <cstdint>
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
  /// (a diagonal block's Cholesky fails) or a value is not finite. After a successful factorisation,
  /// only the rows whose values differ from the last ones (bit by bit) and their ancestors in the
  /// elimination tree are recomputed.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  /// The smallest over the largest pivot L_ii^2 of the factor (the D of the equivalent L D L^T), a
  /// conditioning hint; 0 when the last factorisation failed.
  [[nodiscard]] double pivot_ratio() const;
  /// Node rows of L the last factorisation computed (all of them when it started from scratch).
  [[nodiscard]] int rows_refactorised() const { return rows_refactorised_; }
  /// Solves K x = b with the current factor (NaN everywhere when the last factorisation failed).
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// x = L^-T y: the second half of a solve, for `y` in elimination order (the unknowns of the node at
  /// elimination position k at g k .. g k + g - 1), `x` in the original order (NaN everywhere when
  /// the last factorisation failed). With inverse_factor_columns, K^-1 P w = L^-T (L^-1 P) w.
  [[nodiscard]] Eigen::VectorXd solve_transposed_factor(const Eigen::VectorXd& y) const;
  /// The nodes in elimination order (AMD on the node graph), empty before analysis.
  [[nodiscard]] std::span<const int> node_order() const { return order_; }
  /// Unknowns per node (g), 0 before analysis.
  [[nodiscard]] int node_size() const { return size_; }
  /// The g columns of L^-1 P, P the identity columns of the unknowns of `node` (original numbering),
  /// on the only nodes where they can be nonzero: the elimination-tree path from the node to its root.
  /// `path` receives the path's elimination positions (ascending), `columns` one g x g block
  /// (column-major) per path entry. The cost is the path's share of L, not a triangular solve, so a
  /// few nodes' block of K^-1 = (L^-1 P)^T (L^-1 P) is cheap (a capacitance matrix). Both empty when
  /// not factorised.
  void inverse_factor_columns(int node, std::vector<int>& path, std::vector<double>& columns) const;
  /// Blocks of L that inverse_factor_columns(`node`) reads (each a g x g by g x g product), and the
  /// length of its path in `path_length`; 0 when not factorised.
  [[nodiscard]] double path_blocks(int node, int& path_length) const;

 private:
  /// The analysis' arrays are all there (not so in a moved-from object).
  [[nodiscard]] bool analysed() const {
    return order_.size() == static_cast<std::size_t>(nodes_) && row_start_.size() == order_.size() + 1;
  }
  void build_gather(const Eigen::SparseMatrix<double>& lower);
  void build_rows();
  /// Marks in stale_ the rows of L that read a value of `lower` different from last_values_, and their
  /// ancestors; last_values_ takes the new values.
  void mark_changed_rows(const Eigen::SparseMatrix<double>& lower);
  template <int G>
  bool factorize_blocks(const double* values, bool all_rows);
  template <int G>
  void solve_blocks(double* x, bool forward = true) const;
  template <int G>
  void path_columns(int node, std::vector<int>& path, std::vector<double>& columns) const;

  bool factorised_ = false;  // the last factorisation succeeded
  int size_ = 0;       // g: unknowns per node
  int nodes_ = 0;      // N
  int rows_refactorised_ = 0;
  std::size_t value_count_ = 0;  // entries of the analysed lower triangle
  double flops_ = 0.0;
  std::vector<int> order_;       // elimination position -> node (its unknowns are size_ * node + t)
  std::vector<int> position_;    // node -> elimination position
  std::vector<int> parent_;      // elimination tree over positions, -1 at a root
  std::vector<int> column_start_;// N + 1: first block of each column of L below the diagonal
  // K's blocks by row of the elimination order: row k holds K(k, i) for i <= k (the diagonal last);
  // each block's g x g entries (column-major) as indices into lower's values, -1 where K stores none.
  // The diagonal block gathers its lower triangle only (all its Cholesky reads). gather_ is built by the
  // first factorisation, from the node pairs of lower (v, w > v, by v) and their blocks.
  std::vector<int> row_start_, row_column_, gather_, pairs_, pair_block_;
  // The factor: rows and g x g blocks (column-major) of L below the diagonal, column by column (rows
  // ascending, known from the first factorisation on), and the inverses of the diagonal blocks (lower
  // triangular; every use of L(j, j) is a solve with it).
  std::vector<int> rows_;
  std::vector<double> blocks_, diagonal_;
  // The values of the last successful factorisation (empty otherwise) and the rows to recompute.
  std::vector<double> last_values_;
  std::vector<std::uint8_t> stale_;
  // Workspace of the factorisation.
  std::vector<double> work_;
  std::vector<int> flag_, stack_, pattern_;
};

}  // namespace shatter
