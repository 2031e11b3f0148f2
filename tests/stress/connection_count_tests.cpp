// connection-count: the seed's tests 79-90 (dissertation Appendix D) on the faithful heuristic.
#include "algorithms/stress/connection_count/connection_count_model.h"
#include "algorithms/stress/propagation.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

/// A symmetric adjacency from an edge list.
std::vector<std::vector<int>> adjacency(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(n));
  for (const auto& [a, b] : edges) {
    out[static_cast<std::size_t>(a)].push_back(b);
    out[static_cast<std::size_t>(b)].push_back(a);
  }
  return out;
}

/// A chain 0 - 1 - ... - n-1 with piece 0 as the only root.
ConnectionGraph chain(int n) {
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i + 1 < n; ++i) edges.emplace_back(i, i + 1);
  std::vector<std::uint8_t> roots(static_cast<std::size_t>(n), 0);
  roots[0] = 1;
  return ConnectionGraph(adjacency(n, edges), roots);
}

}  // namespace

TEST_CASE("connection-count: three pieces in a line have 1, 2, 1 connections (seed 79-81)", "[stress][connection-count]") {
  const SupportGraph g = graph_of(sliced_box({3, 1, 1}, {1.5, 0, 0}, planes_at(0, {1.0, 2.0})), {}, 1000.0);
  const ConnectionGraph c = ConnectionGraph::from_support_graph(g);
  std::vector<int> counts;
  for (int v = 0; v < g.node_count(); ++v) counts.push_back(c.connection_count(v));
  std::sort(counts.begin(), counts.end());
  CHECK(counts == std::vector<int>{1, 1, 2});
}

TEST_CASE("connection-count: a destroyed part leaves two rootless clusters falling (seed 82)", "[stress][connection-count]") {
  // Root 0 - 1 - 2 (destroyed); 2 - 3 - 4 and 2 - 5 - 6 hang from it.
  ConnectionGraph c(adjacency(7, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {2, 5}, {5, 6}}), {1, 0, 0, 0, 0, 0, 0});
  const DestroyOutcome out = c.part_destroyed(2);
  CHECK(out.destroyed == std::vector<int>{2});
  REQUIRE(out.falling_clusters.size() == 2);
  CHECK(out.falling_clusters[0] == std::vector<int>{3, 4});
  CHECK(out.falling_clusters[1] == std::vector<int>{5, 6});
  CHECK_FALSE(c.gone(0));
  CHECK_FALSE(c.gone(1));  // still connected to the root: nothing happens to it
}

TEST_CASE("connection-count: destroying the single root makes everything fall (seed 83)", "[stress][connection-count]") {
  ConnectionGraph c = chain(5);
  const DestroyOutcome out = c.part_destroyed(0);
  REQUIRE(out.falling_clusters.size() == 1);
  CHECK(out.falling_clusters[0] == std::vector<int>{1, 2, 3, 4});
}

TEST_CASE("connection-count: propagate stress drops two under-supported pieces, or none (seed 84, 85)", "[stress][connection-count]") {
  // Pieces 1 and 2 each rest on roots 0 and 5 and on the pieces 3 and 4 above/beside them: 3 connections.
  // Roots: 0, 5, 6. 1: {3, 4, 0}; 2: {3, 4, 5}; 6 holds 3 and 4 too.
  ConnectionGraph c(adjacency(7, {{1, 3}, {1, 4}, {1, 0}, {2, 3}, {2, 4}, {2, 5}, {3, 6}, {4, 6}}), {1, 0, 0, 0, 0, 1, 1});
  // Seed 85: destroying 3 leaves 1 and 2 with 2 of 3 connections: enough, nothing happens.
  DestroyOutcome first = c.part_destroyed(3);
  CHECK(first.destroyed == std::vector<int>{3});
  CHECK(first.falling_clusters.empty());
  CHECK(c.propagate_stress(3).empty());
  // Seed 84: destroying 4 leaves them 1 of 3: both lack support and are destroyed in turn.
  DestroyOutcome second = c.part_destroyed(4);
  std::vector<int> destroyed = second.destroyed;
  std::sort(destroyed.begin(), destroyed.end());
  CHECK(destroyed == std::vector<int>{1, 2, 4});
  CHECK(c.gone(1));
  CHECK(c.gone(2));
}

TEST_CASE("connection-count: find cluster returns clusters of 1, 10, 100, 1000 and 10000 (seed 86-90)", "[stress][connection-count]") {
  for (const int n : {1, 10, 100, 1000, 10000}) {
    const ConnectionGraph c = chain(n);
    CHECK(c.find_cluster(n - 1).size() == static_cast<std::size_t>(n));
  }
}

TEST_CASE("connection-count: as a stress model it reports rootless clusters and cascades through propagation", "[stress][connection-count]") {
  const SupportGraph g = graph_of(sliced_box({4, 1, 1}, {2, 0, 0}, planes_at(0, {1.0, 2.0, 3.0})),
                                  {box_region({-1, -1, -1}, {0.001, 2, 2})}, 1000.0);
  const ConnectionCountModel model;
  Result<StressResult> intact = model.evaluate(g, Loads{}, Material{});
  REQUIRE(intact.ok());
  CHECK(intact->falling_clusters.empty());
  for (const BondStress& s : intact->bonds) CHECK(s.utilization <= 1.0);
  // Break the bond at x = 2: the two outer slabs form one rootless cluster.
  int middle = 0;
  for (int i = 0; i < g.bond_count(); ++i)
    if (std::abs(g.bonds[static_cast<std::size_t>(i)].centroid.x() - 2.0) < 1e-9) middle = i;
  Result<PropagationResult> r = propagate(model, g, Loads{}, Material{}, std::vector<int>{middle});
  REQUIRE(r.ok());
  REQUIRE(r->result.falling_clusters.size() == 1);
  CHECK(r->result.falling_clusters[0].size() == 2);
}
