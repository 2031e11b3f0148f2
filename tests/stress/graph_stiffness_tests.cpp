// The stiffness assembly of a cascade (graph_stiffness.h): rebuilding only the columns of the nodes
// whose bonds or identity changed gives, bit for bit, the matrix an assembly from scratch gives, over
// a sequence of rounds that break bonds, turn nodes into identity rows and bring bonds back; and the
// pattern (stiffness_pattern.h) against K summed densely from the same bond blocks.
#include "algorithms/core/random.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "fixtures/structures.h"

#include <Eigen/Dense>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

using namespace shatter;
using namespace shatter::fixtures;

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

TEST_CASE("stiffness pattern: K stores exactly the entries some bond makes nonzero, and the diagonal", "[stress]") {
  // Against K summed densely from the same bond blocks: every stored value equals the dense entry,
  // every nonzero of the dense K is stored, the pattern is symmetric, and every stored entry off the
  // diagonal is nonzero in some bond's block there or at the mirrored place. A planar wall stores about a third of its 6 x 6 node blocks (0.36 here); the box
  // is checked for exactness only (its blocks are denser).
  const auto check = [](const SupportGraph& g, double max_fill) {
    GraphStiffness stiffness(g, Material{});
    const std::vector<std::uint8_t> all(g.bonds.size(), 1), none(g.nodes.size(), 0);
    stiffness.assemble(all, none);
    const Eigen::SparseMatrix<double>& k = stiffness.matrix();
    const Eigen::Index n = k.cols();
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    Eigen::MatrixXi touched = Eigen::MatrixXi::Zero(n, n);  // some block nonzero there
    for (int b = 0; b < g.bond_count(); ++b) {
      std::array<Matrix6, 4> blocks;
      bond_blocks(stiffness.spring(b), blocks);
      const int ends[2] = {stiffness.first_unknown(g.bonds[static_cast<std::size_t>(b)].a),
                           stiffness.first_unknown(g.bonds[static_cast<std::size_t>(b)].b)};
      for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y) {
          if (ends[x] < 0 || ends[y] < 0) continue;
          const Matrix6& block = blocks[static_cast<std::size_t>(2 * x + y)];
          dense.block<6, 6>(ends[y], ends[x]) += block;
          touched.block<6, 6>(ends[y], ends[x]) += (block.array() != 0.0).cast<int>().matrix();
        }
    }
    Eigen::MatrixXi stored = Eigen::MatrixXi::Zero(n, n);
    for (int c = 0; c < k.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(k, c); it; ++it) {
        stored(it.row(), it.col()) = 1;
        CHECK(it.value() == dense(it.row(), it.col()));
        if (it.row() != it.col()) CHECK(touched(it.row(), it.col()) + touched(it.col(), it.row()) > 0);
      }
    CHECK(stored == stored.transpose());  // a symmetric pattern: the lower triangle holds all of K
    for (Eigen::Index c = 0; c < n; ++c) {
      CHECK(stored(c, c) == 1);
      for (Eigen::Index r = 0; r < n; ++r)
        if (dense(r, c) != 0.0) CHECK(stored(r, c) == 1);
    }
    // Fill against dense 6 x 6 blocks on every coupled pair (the pattern before this one).
    int pairs = 0;
    for (Eigen::Index c = 0; c < n; c += 6)
      for (Eigen::Index r = 0; r < n; r += 6) pairs += touched.block<6, 6>(r, c).any() || r == c ? 1 : 0;
    const double fill = static_cast<double>(k.nonZeros()) / (36.0 * pairs);
    INFO("stored " << k.nonZeros() << " of " << 36 * pairs);
    CHECK(fill <= max_fill);
  };
  SECTION("a planar wall") { check(block_wall(6, 5), 0.4); }
  SECTION("a 3D box of slabs") {
    std::vector<Plane> cuts = planes_at(0, even_cuts(-1.0, 1.0, 3));
    for (const Plane& p : planes_at(1, even_cuts(-0.75, 0.75, 2))) cuts.push_back(p);
    for (const Plane& p : planes_at(2, even_cuts(0.0, 2.0, 3))) cuts.push_back(p);
    check(graph_of(sliced_box({2.0, 1.5, 2.0}, {0.0, 0.0, 1.0}, cuts), {box_region({-2, -2, -0.1}, {2, 2, 0.1})}, 2400.0),
          1.0);
  }
}

TEST_CASE("stiffness pattern: a zero on one side of a block pair only is stored on both", "[stress]") {
  // Two free nodes, one bond: block (b, a) has a nonzero at row 1, column 0 that block (a, b) lacks at
  // the mirrored place (row 0, column 1), as round-off can leave. The pattern holds both entries, and
  // the lower triangle (which the factorisations read) the one the upper side has.
  std::uint64_t diagonal = 0;
  for (int k = 0; k < 6; ++k) diagonal |= std::uint64_t{1} << (7 * k);
  const std::array<std::array<int, 2>, 1> ends{{{0, 1}}};
  const std::array<std::array<std::uint64_t, 4>, 1> masks{{{diagonal, std::uint64_t{1} << 1, 0, diagonal}}};
  const StiffnessPattern p = build_stiffness_pattern(2, ends, masks);
  Eigen::MatrixXi stored = Eigen::MatrixXi::Zero(12, 12);
  for (int c = 0; c < p.matrix.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(p.matrix, c); it; ++it) stored(it.row(), it.col()) = 1;
  CHECK(stored(6 + 1, 0) == 1);  // block (b, a): row 1 of node b, column 0 of node a
  CHECK(stored(0, 6 + 1) == 1);  // its mirror, which no block makes nonzero
  CHECK(stored == stored.transpose());
  CHECK(p.matrix.nonZeros() == 12 + 2);
}
