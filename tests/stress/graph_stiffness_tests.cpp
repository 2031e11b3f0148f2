// The stiffness assembly of a cascade (graph_stiffness.h): rebuilding only the columns of the nodes
// whose bonds or identity changed gives, bit for bit, the matrix an assembly from scratch gives, over
// a sequence of rounds that break bonds, turn nodes into identity rows and bring bonds back.
#include "algorithms/core/random.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "tests/stress/structures.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

using namespace shatter;
using namespace shatter::test;

TEST_CASE("graph stiffness: assembling only the changed columns equals an assembly from scratch", "[stress]") {
  const SupportGraph g = block_wall(9, 8);
  SplitMix64 random(12);
  GraphStiffness incremental(g, Material{});
  std::vector<std::uint8_t> include(g.bonds.size(), 1), identity(g.nodes.size(), 0);
  int free_nodes = 0;
  for (const SupportNode& n : g.nodes) free_nodes += n.anchored ? 0 : 1;
  CHECK(incremental.assemble(include, identity) == free_nodes);
  CHECK(incremental.assemble(include, identity) == 0);  // nothing changed, nothing rebuilt

  for (int round = 0; round < 12; ++round) {
    INFO("round " << round);
    // Break a few bonds, bring one back now and then, and turn a node into an identity row (which
    // takes all its bonds out, as a falling cluster's nodes are).
    for (int i = 0; i < 4; ++i) include[static_cast<std::size_t>(random.uniform() * 0.9999 * g.bond_count())] = 0;
    if (round % 3 == 2) include[static_cast<std::size_t>(random.uniform() * 0.9999 * g.bond_count())] = 1;
    const int v = static_cast<int>(random.uniform() * 0.9999 * g.node_count());
    identity[static_cast<std::size_t>(v)] = round % 4 != 3;
    for (std::size_t w = 0; w < identity.size(); ++w)
      if (identity[w])
        for (const int b : g.node_bonds[w]) include[static_cast<std::size_t>(b)] = 0;

    const int rebuilt = incremental.assemble(include, identity);
    CHECK(rebuilt > 0);
    CHECK(rebuilt < free_nodes);
    GraphStiffness fresh(g, Material{});
    fresh.assemble(include, identity);
    const Eigen::SparseMatrix<double>& a = incremental.matrix();
    const Eigen::SparseMatrix<double>& b = fresh.matrix();
    REQUIRE(a.nonZeros() == b.nonZeros());
    CHECK(std::memcmp(a.valuePtr(), b.valuePtr(), sizeof(double) * static_cast<std::size_t>(a.nonZeros())) == 0);
  }
}
