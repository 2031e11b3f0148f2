#pragma once
/// The stiffness matrix of every free node of a support graph in one fixed compressed-column pattern:
/// the pattern of the intact graph (stiffness_pattern.h), whatever is broken.
///
/// Design note: a cascade changes K only by removing bonds, so the pattern, the scatter positions of
/// every bond's 6 x 6 blocks and the blocks themselves are computed once per graph and material; a
/// round re-assembles by adding the blocks of the bonds still included into the zeroed values, in
/// bond order (the same sums, bit for bit, as an assembly of the component alone). Only the columns of
/// the nodes whose bonds or identity changed since the last assembly are rebuilt, adding in the same
/// bond order, so the values are those of an assembly from scratch bit for bit (and a refactorisation
/// sees exactly which rows changed, node_block_cholesky.h). Nodes that are not
/// solved (falling clusters) get identity rows, so the matrix stays positive definite with the
/// same pattern and its ordering and symbolic factorisation stay valid.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/material.h"
#include "algorithms/stress/rigid_body_spring/bond_spring.h"
#include "algorithms/stress/rigid_body_spring/stiffness_pattern.h"

#include <Eigen/SparseCore>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

class GraphStiffness {
 public:
  /// Pattern, springs and scatter positions of every bond of `graph` (6 unknowns per free node).
  GraphStiffness(const SupportGraph& graph, const Material& material);

  /// #unknowns: 6 per node that is not anchored.
  [[nodiscard]] int unknowns() const { return static_cast<int>(matrix_.cols()); }
  /// Index of node `v`'s first unknown (its 6 are consecutive), -1 when anchored.
  [[nodiscard]] int first_unknown(int v) const { return first_[static_cast<std::size_t>(v)]; }
  /// Index in the value array of the diagonal entry of unknown `i`.
  [[nodiscard]] int diagonal_index(int i) const { return diagonal_[static_cast<std::size_t>(i)]; }
  /// The spring of bond `b`.
  [[nodiscard]] const BondSpring& spring(int b) const { return springs_[static_cast<std::size_t>(b)]; }
  /// K = the springs of the bonds with `include_bond[b] != 0` (#bonds) plus the identity on the unknowns
  /// of the nodes with `identity_node[v] != 0` (#nodes; such nodes must have no included bond). Returns
  /// the number of nodes whose columns were rebuilt (all free nodes on the first call).
  int assemble(std::span<const std::uint8_t> include_bond, std::span<const std::uint8_t> identity_node);
  /// The nodes whose columns the last assembly rebuilt (every free node the first time): the others'
  /// columns hold the values they held before it.
  [[nodiscard]] std::span<const int> rebuilt_nodes() const { return changed_nodes_; }
  /// The last assembled K: both triangles, #unknowns square, rows sorted in every column.
  [[nodiscard]] const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

 private:
  std::vector<int> first_;                    // #nodes
  std::vector<int> diagonal_;                 // #unknowns
  std::vector<BondSpring> springs_;           // #bonds
  // 4 #bonds: bond b's blocks from 4 b on, (y, x) = (a, a), (b, a), (a, b), (b, b). Matrix6 elements,
  // not arrays of four, so that sizing the vector does not zero them.
  std::vector<Matrix6> blocks_;
  std::vector<NodePairEntries> pairs_;        // stiffness_pattern.h
  std::vector<std::array<int, 4>> bond_pairs_;// #bonds: the pair of each block, -1 at an anchored end
  std::vector<std::array<int, 2>> bond_ends_; // #bonds: a, b
  std::vector<std::vector<int>> node_bonds_;  // #nodes: bonds at the node, ascending
  Eigen::SparseMatrix<double> matrix_;
  // The flags of the last assembly and the nodes to rebuild.
  bool assembled_ = false;
  std::vector<std::uint8_t> last_include_, last_identity_, changed_;
  std::vector<int> changed_nodes_;

  /// Adds block q (the order of blocks_) of bond b into the values.
  void add_block(std::size_t b, std::size_t q);
  void assemble_all(std::span<const std::uint8_t> include_bond, std::span<const std::uint8_t> identity_node);
  void assemble_columns(int v, std::span<const std::uint8_t> include_bond, bool identity);
};

}  // namespace shatter
