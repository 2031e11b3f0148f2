#include "algorithms/core/node_ordering.h"

#include <amd.h>

#include <algorithm>
#include <cassert>

namespace shatter {

std::optional<std::vector<int>> node_amd_order(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups) {
  // The graph between nodes, one column per node: the nodes of the rows below the diagonal of its
  // columns, each once (a node's columns are consecutive; AMD orders the pattern of G + G^T).
  const int n = static_cast<int>(lower.cols());
  assert(static_cast<int>(groups.size()) == n);
  const int node_count = n > 0 ? groups[static_cast<std::size_t>(n - 1)] + 1 : 0;
  std::vector<int> outer(static_cast<std::size_t>(node_count) + 1, 0), rows;
  std::vector<int> mark(static_cast<std::size_t>(node_count), -1);
  const int* lower_outer = lower.outerIndexPtr();
  const int* lower_inner = lower.innerIndexPtr();
  for (int c = 0; c < n; ++c) {
    const int gc = groups[static_cast<std::size_t>(c)];
    assert(gc >= 0 && gc < node_count && (c == 0 || gc >= groups[static_cast<std::size_t>(c - 1)]));
    for (int at = lower_outer[c]; at < lower_outer[c + 1]; ++at) {
      const int gr = groups[static_cast<std::size_t>(lower_inner[at])];
      if (gr != gc && mark[static_cast<std::size_t>(gr)] != gc) {
        mark[static_cast<std::size_t>(gr)] = gc;
        rows.push_back(gr);
      }
    }
    outer[static_cast<std::size_t>(gc) + 1] = static_cast<int>(rows.size());
  }
  for (std::size_t g = 0; g < static_cast<std::size_t>(node_count); ++g)  // an id with no column: empty
    outer[g + 1] = std::max(outer[g + 1], outer[g]);
  std::vector<int> order(static_cast<std::size_t>(node_count));
  if (rows.empty()) {  // no two nodes coupled: any order, and AMD refuses an empty pattern
    for (int g = 0; g < node_count; ++g) order[static_cast<std::size_t>(g)] = g;
    return order;
  }
  const int status = amd_order(node_count, outer.data(), rows.data(), order.data(), nullptr, nullptr);
  if (status != AMD_OK && status != AMD_OK_BUT_JUMBLED) return std::nullopt;
  return order;
}

}  // namespace shatter
