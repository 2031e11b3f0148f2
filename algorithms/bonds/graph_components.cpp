#include "algorithms/bonds/graph_components.h"

#include <cassert>
#include <numeric>

namespace shatter {

namespace {

/// Union-find with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<std::size_t>(n)), size_(static_cast<std::size_t>(n), 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int x) {
    while (parent_[static_cast<std::size_t>(x)] != x) {
      auto& p = parent_[static_cast<std::size_t>(x)];
      p = parent_[static_cast<std::size_t>(p)];
      x = p;
    }
    return x;
  }
  void unite(int x, int y) {
    x = find(x);
    y = find(y);
    if (x == y) return;
    if (size_[static_cast<std::size_t>(x)] < size_[static_cast<std::size_t>(y)]) std::swap(x, y);
    parent_[static_cast<std::size_t>(y)] = x;
    size_[static_cast<std::size_t>(x)] += size_[static_cast<std::size_t>(y)];
  }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

}  // namespace

GraphComponents graph_components(const SupportGraph& graph, std::span<const std::uint8_t> broken) {
  assert(broken.empty() || broken.size() == graph.bonds.size());
  const int n = graph.node_count();
  DisjointSets sets(n);
  for (int i = 0; i < graph.bond_count(); ++i)
    if (broken.empty() || !broken[static_cast<std::size_t>(i)])
      sets.unite(graph.bonds[static_cast<std::size_t>(i)].a, graph.bonds[static_cast<std::size_t>(i)].b);

  GraphComponents out;
  out.component_of.assign(static_cast<std::size_t>(n), -1);
  std::vector<int> of_root(static_cast<std::size_t>(n), -1);
  for (int v = 0; v < n; ++v) {
    int& c = of_root[static_cast<std::size_t>(sets.find(v))];
    if (c < 0) {
      c = static_cast<int>(out.nodes.size());
      out.nodes.emplace_back();
      out.bonds.emplace_back();
      out.anchored.push_back(0);
    }
    out.component_of[static_cast<std::size_t>(v)] = c;
    out.nodes[static_cast<std::size_t>(c)].push_back(v);
    if (graph.nodes[static_cast<std::size_t>(v)].anchored) out.anchored[static_cast<std::size_t>(c)] = 1;
  }
  for (int i = 0; i < graph.bond_count(); ++i)
    if (broken.empty() || !broken[static_cast<std::size_t>(i)])
      out.bonds[static_cast<std::size_t>(out.component_of[static_cast<std::size_t>(graph.bonds[static_cast<std::size_t>(i)].a)])]
          .push_back(i);
  return out;
}

std::vector<std::vector<int>> falling_clusters(const GraphComponents& components) {
  std::vector<std::vector<int>> out;
  for (std::size_t c = 0; c < components.nodes.size(); ++c)
    if (!components.anchored[c]) out.push_back(components.nodes[c]);
  return out;
}

}  // namespace shatter
