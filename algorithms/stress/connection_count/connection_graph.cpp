#include "algorithms/stress/connection_count/connection_graph.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace shatter {

ConnectionGraph::ConnectionGraph(std::vector<std::vector<int>> neighbours, std::vector<std::uint8_t> roots,
                                 ConnectionCountSettings settings)
    : neighbours_(std::move(neighbours)), roots_(std::move(roots)), settings_(settings) {
  assert(roots_.size() == neighbours_.size());
  for (const auto& list : neighbours_) {
    original_.push_back(static_cast<int>(list.size()));
    intact_.push_back(static_cast<int>(list.size()));
  }
  gone_.assign(neighbours_.size(), 0);
}

ConnectionGraph ConnectionGraph::from_support_graph(const SupportGraph& graph, ConnectionCountSettings settings) {
  std::vector<std::vector<int>> neighbours(graph.nodes.size());
  for (const Bond& e : graph.bonds) {
    neighbours[static_cast<std::size_t>(e.a)].push_back(e.b);
    neighbours[static_cast<std::size_t>(e.b)].push_back(e.a);
  }
  for (auto& list : neighbours) {  // two bonds between one pair are one connection
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<std::uint8_t> roots;
  for (const SupportNode& n : graph.nodes) roots.push_back(n.anchored ? 1 : 0);
  return ConnectionGraph(std::move(neighbours), std::move(roots), settings);
}

double ConnectionGraph::required(int piece) const {
  if (roots_[static_cast<std::size_t>(piece)]) return 0.0;
  return std::max(static_cast<double>(settings_.min_connections),
                  settings_.min_support_fraction * original_[static_cast<std::size_t>(piece)]);
}

std::vector<int> ConnectionGraph::propagate_stress(int piece) const {
  std::vector<int> failing;
  for (const int nb : neighbours_[static_cast<std::size_t>(piece)])
    if (!gone(nb) && !supported(nb)) failing.push_back(nb);
  return failing;
}

std::vector<int> ConnectionGraph::find_cluster(int piece) const {
  // Iterative depth-first search: a chain of 10,000 pieces must not overflow the call stack.
  std::vector<int> cluster;
  if (gone(piece)) return cluster;
  std::vector<std::uint8_t> seen(neighbours_.size(), 0);
  std::vector<int> stack = {piece};
  seen[static_cast<std::size_t>(piece)] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    cluster.push_back(v);
    for (const int w : neighbours_[static_cast<std::size_t>(v)])
      if (!gone(w) && !seen[static_cast<std::size_t>(w)]) {
        seen[static_cast<std::size_t>(w)] = 1;
        stack.push_back(w);
      }
  }
  std::sort(cluster.begin(), cluster.end());
  return cluster;
}

DestroyOutcome ConnectionGraph::part_destroyed(int piece) {
  DestroyOutcome out;
  std::vector<int> queue = {piece};
  std::vector<int> border;  // live neighbours of destroyed pieces: where floating clusters can start
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int x = queue[q];
    if (gone(x)) continue;
    gone_[static_cast<std::size_t>(x)] = 1;
    out.destroyed.push_back(x);
    for (const int nb : neighbours_[static_cast<std::size_t>(x)])
      if (!gone(nb)) {
        --intact_[static_cast<std::size_t>(nb)];
        border.push_back(nb);
      }
    for (const int nb : propagate_stress(x)) queue.push_back(nb);
  }
  for (const int start : border) {
    if (gone(start)) continue;
    std::vector<int> cluster = find_cluster(start);
    const bool rooted = std::any_of(cluster.begin(), cluster.end(),
                                    [&](int v) { return roots_[static_cast<std::size_t>(v)] != 0; });
    if (rooted) continue;
    for (const int v : cluster) gone_[static_cast<std::size_t>(v)] = 1;  // it falls: out of the structure
    out.falling_clusters.push_back(std::move(cluster));
  }
  return out;
}

}  // namespace shatter
