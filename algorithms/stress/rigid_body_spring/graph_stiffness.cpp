#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"

#include <algorithm>
#include <cassert>

namespace shatter {

GraphStiffness::GraphStiffness(const SupportGraph& graph, const Material& material) {
  first_.assign(graph.nodes.size(), -1);
  int nf = 0;
  for (std::size_t v = 0; v < graph.nodes.size(); ++v)
    if (!graph.nodes[v].anchored) first_[v] = 6 * nf++;
  const int n = 6 * nf;

  // Column pattern: node i's columns hold the 6 rows of i and of every free neighbour, sorted.
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(nf));
  for (std::size_t v = 0; v < graph.nodes.size(); ++v)
    if (first_[v] >= 0) neighbours[static_cast<std::size_t>(first_[v] / 6)].push_back(first_[v] / 6);
  for (const Bond& e : graph.bonds) {
    const int la = first_[static_cast<std::size_t>(e.a)], lb = first_[static_cast<std::size_t>(e.b)];
    if (la >= 0 && lb >= 0) {
      neighbours[static_cast<std::size_t>(la / 6)].push_back(lb / 6);
      neighbours[static_cast<std::size_t>(lb / 6)].push_back(la / 6);
    }
  }
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0);
  for (int i = 0; i < nf; ++i) {
    auto& list = neighbours[static_cast<std::size_t>(i)];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    for (int k = 0; k < 6; ++k) outer[static_cast<std::size_t>(6 * i + k + 1)] = 6 * static_cast<int>(list.size());
  }
  for (int c = 0; c < n; ++c) outer[static_cast<std::size_t>(c + 1)] += outer[static_cast<std::size_t>(c)];
  matrix_.resize(n, n);
  matrix_.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), matrix_.outerIndexPtr());
  int* inner = matrix_.innerIndexPtr();
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + outer.back(), 0.0);
  diagonal_.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k) {
      int at = outer[static_cast<std::size_t>(6 * i + k)];
      for (const int j : neighbours[static_cast<std::size_t>(i)])
        for (int r = 0; r < 6; ++r) {
          if (6 * j + r == 6 * i + k) diagonal_[static_cast<std::size_t>(6 * i + k)] = at;
          inner[at++] = 6 * j + r;
        }
    }
  // Block (row node j, column node i) starts in column 6 i at slot j of i's neighbour list.
  auto slot = [&](int j, int i) {
    if (j < 0 || i < 0) return Slot{};
    const auto& list = neighbours[static_cast<std::size_t>(i / 6)];
    const int at = static_cast<int>(std::lower_bound(list.begin(), list.end(), j / 6) - list.begin());
    return Slot{outer[static_cast<std::size_t>(i)] + 6 * at, 6 * static_cast<int>(list.size())};
  };

  springs_.resize(graph.bonds.size());
  blocks_.resize(graph.bonds.size());
  slots_.resize(graph.bonds.size());
  bond_ends_.resize(graph.bonds.size());
  node_bonds_.resize(graph.nodes.size());
  for (std::size_t b = 0; b < graph.bonds.size(); ++b) {
    const Bond& e = graph.bonds[b];
    assert(e.a != e.b);
    bond_ends_[b] = {e.a, e.b};
    node_bonds_[static_cast<std::size_t>(e.a)].push_back(static_cast<int>(b));  // ascending: b ascends
    node_bonds_[static_cast<std::size_t>(e.b)].push_back(static_cast<int>(b));
    const BondSpring& s = springs_[b] = bond_spring(graph, static_cast<int>(b), material);
    blocks_[b] = bond_blocks(s);
    const int ends[2] = {first_[static_cast<std::size_t>(e.a)], first_[static_cast<std::size_t>(e.b)]};
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y) slots_[b][static_cast<std::size_t>(2 * x + y)] = slot(ends[y], ends[x]);
  }
  structural_.assign(static_cast<std::size_t>(outer.back()), 0);
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    for (std::size_t q = 0; q < 4; ++q) {
      const Slot s = slots_[b][q];
      if (s.start < 0) continue;
      for (int k = 0; k < 6; ++k)
        for (int r = 0; r < 6; ++r)
          if (blocks_[b][q](r, k) != 0.0) structural_[static_cast<std::size_t>(s.start + k * s.stride + r)] = 1;
    }
}

void GraphStiffness::add_block(std::size_t b, std::size_t q) {
  const Slot s = slots_[b][q];
  if (s.start < 0) return;
  const Matrix6& block = blocks_[b][q];
  double* value = matrix_.valuePtr();
  for (int k = 0; k < 6; ++k) {
    double* column = value + s.start + k * s.stride;
    for (int r = 0; r < 6; ++r) column[r] += block(r, k);
  }
}

int GraphStiffness::assemble(std::span<const std::uint8_t> include_bond, std::span<const std::uint8_t> identity_node) {
  const std::size_t nodes = first_.size();
  if (last_include_.empty()) {
    assemble_all(include_bond, identity_node);
  } else {
    // The nodes at either end of a bond whose inclusion changed, and those whose identity changed.
    const auto mark = [&](int v) {
      if (first_[static_cast<std::size_t>(v)] >= 0 && !changed_[static_cast<std::size_t>(v)]) {
        changed_[static_cast<std::size_t>(v)] = 1;
        changed_nodes_.push_back(v);
      }
    };
    changed_nodes_.clear();
    for (std::size_t b = 0; b < blocks_.size(); ++b)
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
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
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
