#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"

#include <algorithm>
#include <cassert>

namespace shatter {

GraphStiffness::GraphStiffness(const SupportGraph& graph, const Material& material) {
  first_.assign(graph.nodes.size(), -1);
  int nf = 0;
  for (std::size_t v = 0; v < graph.nodes.size(); ++v)
    if (!graph.nodes[v].anchored) first_[v] = 6 * nf++;

  springs_.resize(graph.bonds.size());
  blocks_.resize(4 * graph.bonds.size());
  bond_ends_.resize(graph.bonds.size());
  node_bonds_.resize(graph.nodes.size());
  std::vector<std::array<int, 2>> free_ends(graph.bonds.size());
  std::vector<std::array<std::uint64_t, 4>> masks(graph.bonds.size());
  for (std::size_t b = 0; b < graph.bonds.size(); ++b) {
    const Bond& e = graph.bonds[b];
    assert(e.a != e.b);
    springs_[b] = bond_spring(graph, static_cast<int>(b), material);
    const std::span<Matrix6, 4> blocks(blocks_.data() + 4 * b, 4);
    bond_blocks(springs_[b], blocks);
    for (std::size_t q = 0; q < 4; ++q) masks[b][q] = nonzero_mask(blocks[q]);
    bond_ends_[b] = {e.a, e.b};
    node_bonds_[static_cast<std::size_t>(e.a)].push_back(static_cast<int>(b));  // ascending: b ascends
    node_bonds_[static_cast<std::size_t>(e.b)].push_back(static_cast<int>(b));
    const int la = first_[static_cast<std::size_t>(e.a)], lb = first_[static_cast<std::size_t>(e.b)];
    free_ends[b] = {la >= 0 ? la / 6 : -1, lb >= 0 ? lb / 6 : -1};
  }
  StiffnessPattern pattern = build_stiffness_pattern(nf, free_ends, masks);
  matrix_.swap(pattern.matrix);  // Eigen's SparseMatrix copies on a move
  diagonal_ = std::move(pattern.diagonal);
  pairs_ = std::move(pattern.pairs);
  bond_pairs_ = std::move(pattern.bond_pairs);
}

void GraphStiffness::add_block(std::size_t b, std::size_t q) {
  if (const int p = bond_pairs_[b][q]; p >= 0) add_pair_block(matrix_.valuePtr(), blocks_[4 * b + q], pairs_[static_cast<std::size_t>(p)]);
}

int GraphStiffness::assemble(std::span<const std::uint8_t> include_bond, std::span<const std::uint8_t> identity_node) {
  const std::size_t nodes = first_.size();
  if (!assembled_) {
    assemble_all(include_bond, identity_node);
    assembled_ = true;
  } else {
    // The nodes at either end of a bond whose inclusion changed, and those whose identity changed.
    const auto mark = [&](int v) {
      if (first_[static_cast<std::size_t>(v)] >= 0 && !changed_[static_cast<std::size_t>(v)]) {
        changed_[static_cast<std::size_t>(v)] = 1;
        changed_nodes_.push_back(v);
      }
    };
    changed_nodes_.clear();
    for (std::size_t b = 0; b < springs_.size(); ++b)
      if ((include_bond[b] != 0) != (last_include_[b] != 0)) {
        mark(bond_ends_[b][0]);
        mark(bond_ends_[b][1]);
      }
    for (std::size_t v = 0; v < nodes; ++v)
      if ((identity_node[v] != 0) != (last_identity_[v] != 0)) mark(static_cast<int>(v));
    for (const int v : changed_nodes_) {
      changed_[static_cast<std::size_t>(v)] = 0;
      assemble_columns(v, include_bond, identity_node[static_cast<std::size_t>(v)] != 0);
    }
  }
  last_include_.assign(include_bond.begin(), include_bond.end());
  last_identity_.assign(identity_node.begin(), identity_node.end());
  return static_cast<int>(changed_nodes_.size());
}

void GraphStiffness::assemble_all(std::span<const std::uint8_t> include_bond, std::span<const std::uint8_t> identity_node) {
  double* value = matrix_.valuePtr();
  std::fill(value, value + matrix_.nonZeros(), 0.0);
  for (std::size_t b = 0; b < springs_.size(); ++b) {
    if (!include_bond[b]) continue;
    for (std::size_t q = 0; q < 4; ++q) add_block(b, q);
  }
  changed_nodes_.clear();
  for (std::size_t v = 0; v < identity_node.size(); ++v) {
    if (first_[v] < 0) continue;
    changed_nodes_.push_back(static_cast<int>(v));
    if (identity_node[v])
      for (int k = 0; k < 6; ++k) value[diagonal_[static_cast<std::size_t>(first_[v] + k)]] = 1.0;
  }
  changed_.assign(first_.size(), 0);
}

void GraphStiffness::assemble_columns(int v, std::span<const std::uint8_t> include_bond, bool identity) {
  // Column node v holds blocks (a, a), (b, a) of the bonds whose end a is v, (a, b), (b, b) of those
  // whose end b is v. Added in ascending bond order, as assemble_all adds them.
  const int first = first_[static_cast<std::size_t>(v)];
  const int* outer = matrix_.outerIndexPtr();
  double* value = matrix_.valuePtr();
  std::fill(value + outer[first], value + outer[first + 6], 0.0);
  for (const int b : node_bonds_[static_cast<std::size_t>(v)]) {
    if (!include_bond[static_cast<std::size_t>(b)]) continue;
    const std::size_t q0 = bond_ends_[static_cast<std::size_t>(b)][0] == v ? 0 : 2;
    add_block(static_cast<std::size_t>(b), q0);
    add_block(static_cast<std::size_t>(b), q0 + 1);
  }
  if (identity)
    for (int k = 0; k < 6; ++k) value[diagonal_[static_cast<std::size_t>(first + k)]] = 1.0;
}

}  // namespace shatter
