#pragma once
/// Connected components of a support graph over its intact bonds, and which of them hang free.

#include "algorithms/bonds/support_graph.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// The components of the graph restricted to intact bonds.
struct GraphComponents {
  std::vector<int> component_of;              ///< #nodes: component index of each node
  std::vector<std::vector<int>> nodes;        ///< #components: node indices, ascending
  std::vector<std::vector<int>> bonds;        ///< #components: intact bond indices, ascending
  std::vector<std::uint8_t> anchored;         ///< #components: 1 when a node of it is anchored
};

/// Components by union-find over the bonds with `broken[i] == 0` (`broken` empty: all intact).
/// Components are numbered in order of their smallest node.
GraphComponents graph_components(const SupportGraph& graph, std::span<const std::uint8_t> broken = {});

/// The node lists of the components with no anchored node (falling clusters), in component order.
std::vector<std::vector<int>> falling_clusters(const GraphComponents& components);

}  // namespace shatter
