// The node-block sparse Cholesky (node_block_cholesky.h) against dense Cholesky solves of random
// symmetric positive definite block-sparse matrices, its flop count on a pattern whose factor is known,
// its refusals: not positive definite, nodes of mixed sizes; its refactorisation of the changed rows
// only, against the rows found on dense factors; and the choice between node blocks and CHOLMOD
// (sparse_cholesky.h).

#include "algorithms/core/node_block_cholesky.h"
#include "algorithms/core/random.h"
#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <span>
#include <vector>

using namespace shatter;

namespace {

/// A random SPD matrix of `nodes` nodes of `g` unknowns: B^T B + I over a random sparse node graph
/// (each node coupled to up to 3 random others), stored as its lower triangle with node groups.
struct BlockSystem {
  Eigen::SparseMatrix<double> lower;
  Eigen::MatrixXd dense;
  std::vector<int> groups;
};

BlockSystem random_block_system(SplitMix64& random, int nodes, int g) {
  const int n = nodes * g;
  // B: one row block per bond between two nodes, with random g x g blocks at both ends.
  std::vector<Eigen::Triplet<double>> b;
  int row = 0;
  for (int v = 0; v < nodes; ++v)
    for (int e = 0; e < 3; ++e) {
      const int w = static_cast<int>(random.uniform() * nodes * 0.9999);
      if (w == v) continue;
      for (int r = 0; r < g; ++r)
        for (int c = 0; c < g; ++c) {
          b.emplace_back(row + r, v * g + c, random.uniform(-1, 1));
          b.emplace_back(row + r, w * g + c, random.uniform(-1, 1));
        }
      row += g;
    }
  Eigen::SparseMatrix<double> bm(row, n);
  bm.setFromTriplets(b.begin(), b.end());
  Eigen::SparseMatrix<double> k = Eigen::SparseMatrix<double>(bm.transpose()) * bm;
  for (int i = 0; i < n; ++i) k.coeffRef(i, i) += 1.0;
  BlockSystem s;
  s.dense = Eigen::MatrixXd(k);
  s.lower = k.triangularView<Eigen::Lower>();
  s.lower.makeCompressed();
  for (int i = 0; i < n; ++i) s.groups.push_back(i / g);
  return s;
}

}  // namespace

TEST_CASE("node-block Cholesky: solves random block-sparse SPD systems as a dense Cholesky does", "[stress]") {
  SplitMix64 random(7);
  for (int g = 1; g <= NodeBlockCholesky::kMaxNodeSize; ++g)
    for (int trial = 0; trial < 4; ++trial) {
      const int nodes = 5 + 20 * trial;
      INFO("node size " << g << ", nodes " << nodes);
      const BlockSystem s = random_block_system(random, nodes, g);
      NodeBlockCholesky cholesky;
      REQUIRE(cholesky.analyze(s.lower, s.groups));
      REQUIRE(cholesky.factorize(s.lower));
      Eigen::VectorXd b(s.dense.rows());
      for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = random.uniform(-1, 1);
      const Eigen::VectorXd expected = s.dense.llt().solve(b);
      const Eigen::VectorXd x = cholesky.solve(b);
      CHECK((x - expected).norm() <= 1e-10 * expected.norm());
      // Factorising new values in the same pattern: scale K, the solution scales back.
      Eigen::SparseMatrix<double> doubled = 2.0 * s.lower;
      REQUIRE(cholesky.factorize(doubled));
      CHECK((2.0 * cholesky.solve(b) - expected).norm() <= 1e-10 * expected.norm());
    }
}

TEST_CASE("node-block Cholesky: one unknown per node without groups", "[stress]") {
  SplitMix64 random(8);
  const BlockSystem s = random_block_system(random, 60, 1);
  NodeBlockCholesky cholesky;
  REQUIRE(cholesky.analyze(s.lower));
  REQUIRE(cholesky.factorize(s.lower));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(60, -1.0, 2.0);
  const Eigen::VectorXd expected = s.dense.llt().solve(b);
  CHECK((cholesky.solve(b) - expected).norm() <= 1e-10 * expected.norm());
}

TEST_CASE("node-block Cholesky: flops of a chain of nodes, whose factor has no fill", "[stress]") {
  // A path of N nodes of g unknowns, dense blocks on and next to the diagonal: any elimination order
  // AMD finds for a path has no fill, so L has one block below the diagonal in all but one column.
  // Counted per scalar column (entries squared): sum over t of (c g + g - t)^2 with c = 1 (N - 1 times)
  // and c = 0 (once).
  for (int g = 1; g <= 3; ++g) {
    const int nodes = 30, n = nodes * g;
    Eigen::SparseMatrix<double> lower(n, n);
    std::vector<Eigen::Triplet<double>> t;
    for (int v = 0; v < nodes; ++v)
      for (int c = 0; c < g; ++c) {
        for (int r = c; r < g; ++r) t.emplace_back(v * g + r, v * g + c, r == c ? 4.0 * g : 0.5);
        if (v + 1 < nodes)
          for (int r = 0; r < g; ++r) t.emplace_back((v + 1) * g + r, v * g + c, -0.25);
      }
    lower.setFromTriplets(t.begin(), t.end());
    lower.makeCompressed();
    std::vector<int> groups;
    for (int i = 0; i < n; ++i) groups.push_back(i / g);
    NodeBlockCholesky cholesky;
    REQUIRE(cholesky.analyze(lower, groups));
    double expected = 0.0;
    for (int t2 = 0; t2 < g; ++t2) {
      const double below = g + (g - t2), last = g - t2;
      expected += (nodes - 1) * below * below + last * last;
    }
    CHECK(cholesky.factor_flops() == expected);
  }
}

TEST_CASE("node-block Cholesky: refuses what it cannot factorise", "[stress]") {
  SplitMix64 random(9);
  BlockSystem s = random_block_system(random, 12, 3);
  NodeBlockCholesky cholesky;
  REQUIRE(cholesky.analyze(s.lower, s.groups));

  SECTION("not positive definite: false, and the same pattern factorises again afterwards") {
    Eigen::SparseMatrix<double> indefinite = s.lower;
    indefinite.coeffRef(20, 20) = -50.0;
    CHECK_FALSE(cholesky.factorize(indefinite));
    REQUIRE(cholesky.factorize(s.lower));
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(36);
    const Eigen::VectorXd expected = s.dense.llt().solve(b);
    CHECK((cholesky.solve(b) - expected).norm() <= 1e-10 * expected.norm());
  }
  SECTION("a value that is not finite") {
    Eigen::SparseMatrix<double> bad = s.lower;
    bad.coeffRef(5, 4) = std::numeric_limits<double>::infinity();
    CHECK_FALSE(cholesky.factorize(bad));
  }
  SECTION("a node whose diagonal block K does not store: singular") {
    std::vector<Eigen::Triplet<double>> t;
    for (int k = 0; k < s.lower.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(s.lower, k); it; ++it)
        if (it.col() / 3 != 4 || it.row() / 3 != 4) t.emplace_back(it.row(), it.col(), it.value());
    Eigen::SparseMatrix<double> hollow(36, 36);
    hollow.setFromTriplets(t.begin(), t.end());
    NodeBlockCholesky h;
    REQUIRE(h.analyze(hollow, s.groups));
    CHECK_FALSE(h.factorize(hollow));
    CHECK_FALSE(h.solve(Eigen::VectorXd::Ones(36)).allFinite());  // no factor: NaN, never a stale one
  }
  SECTION("an entry above the diagonal between two nodes: refused, the object left empty") {
    Eigen::SparseMatrix<double> upper = s.lower;
    upper.coeffRef(0, 35) = 1.0;
    upper.makeCompressed();
    CHECK_FALSE(cholesky.analyze(upper, s.groups));
    CHECK(cholesky.factor_flops() == 0.0);
    CHECK_FALSE(cholesky.factorize(s.lower));
  }
  SECTION("nodes of mixed sizes, or larger than six unknowns") {
    std::vector<int> mixed = s.groups;
    mixed[2] = 1;  // node 0 has two unknowns, node 1 four
    CHECK_FALSE(cholesky.analyze(s.lower, mixed));
    BlockSystem big = random_block_system(random, 4, 7);
    CHECK_FALSE(cholesky.analyze(big.lower, big.groups));
  }
}

TEST_CASE("node-block Cholesky: nodes that couple to nothing, explicit zeros", "[stress]") {
  // One node of six unknowns, and five uncoupled nodes of two: no edge between nodes to order.
  for (const int g : {6, 2}) {
    const int nodes = g == 6 ? 1 : 5, n = nodes * g;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    for (int v = 0; v < nodes; ++v) {
      Eigen::MatrixXd m = Eigen::MatrixXd::Random(g, g);
      dense.block(v * g, v * g, g, g) = m * m.transpose() + Eigen::MatrixXd::Identity(g, g);
    }
    Eigen::SparseMatrix<double> lower = dense.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
    // An explicit zero between the first two unknowns of node 0 (same pattern, value 0).
    lower.coeffRef(1, 0) = 0.0;
    dense(1, 0) = dense(0, 1) = 0.0;
    lower.makeCompressed();
    std::vector<int> groups;
    for (int i = 0; i < n; ++i) groups.push_back(i / g);
    NodeBlockCholesky cholesky;
    REQUIRE(cholesky.analyze(lower, groups));
    REQUIRE(cholesky.factorize(lower));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    const Eigen::VectorXd expected = dense.llt().solve(b);
    CHECK((cholesky.solve(b) - expected).norm() <= 1e-12 * expected.norm());
  }
}

TEST_CASE("sparse Cholesky: node blocks for small factorisations, CHOLMOD for large ones", "[stress]") {
  SplitMix64 random(10);
  const BlockSystem small = random_block_system(random, 40, 3);
  SparseCholesky a;
  REQUIRE(a.analyze(small.lower, small.groups));
  CHECK(a.by_node_blocks());
  CHECK(a.factor_flops() <= kNodeBlockMaxFlops);
  // A dense matrix of 840 unknowns: about 840^3 / 3 = 2.0e8 flops, above the limit.
  const int n = 840;
  Eigen::MatrixXd m = Eigen::MatrixXd::Random(n, n) / n;
  Eigen::MatrixXd dense = m * m.transpose() + Eigen::MatrixXd::Identity(n, n);
  const Eigen::SparseMatrix<double> lower = dense.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
  std::vector<int> groups(n);
  for (int i = 0; i < n; ++i) groups[static_cast<std::size_t>(i)] = i / 6;
  SparseCholesky b;
  REQUIRE(b.analyze(lower, groups));
  CHECK_FALSE(b.by_node_blocks());
  CHECK(b.factor_flops() > kNodeBlockMaxFlops);
  REQUIRE(b.factorize(lower));
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(n);
  const Eigen::VectorXd expected = dense.llt().solve(rhs);
  CHECK((b.solve(rhs) - expected).norm() <= 1e-10 * expected.norm());

  // Nodes of two sizes (a node of 3 unknowns, then nodes of 2): CHOLMOD, however small.
  std::vector<int> mixed{0, 0, 0};
  for (int i = 3; i < 41; ++i) mixed.push_back(1 + (i - 3) / 2);
  const BlockSystem odd = random_block_system(random, 41, 1);
  SparseCholesky c;
  REQUIRE(c.analyze(odd.lower, mixed));
  CHECK_FALSE(c.by_node_blocks());
  REQUIRE(c.factorize(odd.lower));
  const Eigen::VectorXd r41 = Eigen::VectorXd::Ones(41);
  const Eigen::VectorXd e41 = odd.dense.llt().solve(r41);
  CHECK((c.solve(r41) - e41).norm() <= 1e-10 * e41.norm());
}

namespace {

/// For K changed from `a` to `b`, with the nodes in elimination order `order`: the node rows of L that
/// must be recomputed (the rows where P K P^T changed in the lower triangle, and their ancestors in
/// the elimination tree of the dense factor of P a P^T: parent of j = the first node row below j
/// with a nonzero in column j), and the node rows where the dense factors of P a P^T and P b P^T
/// actually differ (a subset: a change can round away before it reaches a far ancestor).
struct RowsToRecompute {
  int needed = 0, differ = 0;
};

RowsToRecompute rows_to_recompute(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, std::span<const int> order, int g) {
  const Eigen::Index n = a.rows(), nodes = n / g;
  Eigen::PermutationMatrix<Eigen::Dynamic> p(n);  // unknown of node order[k] -> position k
  for (std::size_t k = 0; k < order.size(); ++k)
    for (int t = 0; t < g; ++t) p.indices()[order[k] * g + t] = static_cast<int>(k) * g + t;
  const Eigen::MatrixXd pa = p * a * p.transpose(), pb = p * b * p.transpose();
  const Eigen::MatrixXd la = Eigen::MatrixXd(pa.llt().matrixL()), lb = Eigen::MatrixXd(pb.llt().matrixL());
  std::vector<int> parent(static_cast<std::size_t>(nodes), -1);
  for (Eigen::Index j = 0; j < nodes; ++j)
    for (Eigen::Index k = j + 1; k < nodes && parent[static_cast<std::size_t>(j)] < 0; ++k)
      if ((la.block(k * g, j * g, g, g).array() != 0.0).any()) parent[static_cast<std::size_t>(j)] = static_cast<int>(k);
  std::vector<char> marked(static_cast<std::size_t>(nodes), 0);
  for (Eigen::Index k = 0; k < nodes; ++k)
    marked[static_cast<std::size_t>(k)] = (pa.block(k * g, 0, g, (k + 1) * g).array() != pb.block(k * g, 0, g, (k + 1) * g).array()).any();
  RowsToRecompute out;
  for (Eigen::Index k = 0; k < nodes; ++k) {
    if (marked[static_cast<std::size_t>(k)] && parent[static_cast<std::size_t>(k)] >= 0) marked[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])] = 1;
    out.needed += marked[static_cast<std::size_t>(k)];
    out.differ += (la.middleRows(k * g, g).array() != lb.middleRows(k * g, g).array()).any() ? 1 : 0;
  }
  return out;
}

}  // namespace

TEST_CASE("node-block Cholesky: refactorising recomputes exactly the rows that change, as from scratch", "[stress]") {
  // One node's diagonal block is stiffened (K + 0.5 I on its unknowns, still positive definite), or
  // one entry between two nodes changed. The rows to recompute, found on dense matrices (the rows
  // whose K changed and their ancestors in the tree of the dense factor), are those the refactor
  // recomputes, and they hold every row where the dense factors differ; the refactored factor solves
  // bit for bit as a fresh factorisation.
  SplitMix64 random(11);
  for (const int g : {1, 3, 6}) {
    const int nodes = 80;
    const BlockSystem s = random_block_system(random, nodes, g);
    NodeBlockCholesky cholesky;
    REQUIRE(cholesky.analyze(s.lower, s.groups));
    REQUIRE(cholesky.factorize(s.lower));
    CHECK(cholesky.rows_refactorised() == nodes);
    Eigen::VectorXd b(s.dense.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = random.uniform(-1, 1);
    const Eigen::VectorXd before = cholesky.solve(b);

    SECTION("nothing changed: no row recomputed, the same solution") {
      REQUIRE(cholesky.factorize(s.lower));
      CHECK(cholesky.rows_refactorised() == 0);
      CHECK((cholesky.solve(b).array() == before.array()).all());
    }
    SECTION("one node stiffened, for several nodes in turn") {
      for (const int v : {0, 17, 41, nodes - 1}) {
        INFO("node size " << g << ", node " << v);
        Eigen::SparseMatrix<double> stiffer = s.lower;
        Eigen::MatrixXd dense = s.dense;
        for (int t = 0; t < g; ++t) {
          stiffer.coeffRef(v * g + t, v * g + t) += 0.5;
          dense(v * g + t, v * g + t) += 0.5;
        }
        REQUIRE(cholesky.factorize(stiffer));
        const RowsToRecompute expected = rows_to_recompute(s.dense, dense, cholesky.node_order(), g);
        CHECK(cholesky.rows_refactorised() == expected.needed);
        CHECK(expected.differ <= expected.needed);
        CHECK(expected.differ > 0);
        CHECK(expected.needed < nodes);
        NodeBlockCholesky fresh;
        REQUIRE(fresh.analyze(stiffer, s.groups));
        REQUIRE(fresh.factorize(stiffer));
        CHECK((cholesky.solve(b).array() == fresh.solve(b).array()).all());
        const Eigen::VectorXd x = dense.llt().solve(b);
        CHECK((cholesky.solve(b) - x).norm() <= 1e-10 * x.norm());
        REQUIRE(cholesky.factorize(s.lower));  // and back
        CHECK((cholesky.solve(b).array() == before.array()).all());
      }
    }
    SECTION("one entry between two nodes changed (K stays positive definite: its eigenvalues are >= 1)") {
      Eigen::SparseMatrix<double> changed = s.lower;
      Eigen::MatrixXd dense = s.dense;
      bool done = false;
      for (int c = 0; c < changed.outerSize() && !done; ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(changed, c); it && !done; ++it)
          if (it.row() / g != it.col() / g && it.col() / g > nodes / 3) {
            it.valueRef() += 0.1;
            dense(it.row(), it.col()) += 0.1;
            dense(it.col(), it.row()) += 0.1;
            done = true;
          }
      REQUIRE(done);
      REQUIRE(cholesky.factorize(changed));
      const RowsToRecompute expected = rows_to_recompute(s.dense, dense, cholesky.node_order(), g);
      CHECK(cholesky.rows_refactorised() == expected.needed);
      CHECK(expected.differ <= expected.needed);
      CHECK(expected.differ > 0);
      NodeBlockCholesky fresh;
      REQUIRE(fresh.analyze(changed, s.groups));
      REQUIRE(fresh.factorize(changed));
      CHECK((cholesky.solve(b).array() == fresh.solve(b).array()).all());
    }
    SECTION("after a failed factorisation the next one starts from scratch") {
      Eigen::SparseMatrix<double> indefinite = s.lower;
      indefinite.coeffRef(0, 0) = -1.0;
      CHECK_FALSE(cholesky.factorize(indefinite));
      REQUIRE(cholesky.factorize(s.lower));
      CHECK(cholesky.rows_refactorised() == nodes);
      CHECK((cholesky.solve(b).array() == before.array()).all());
    }
  }
}

TEST_CASE("node-block Cholesky: the pivot ratio of a diagonal matrix is its smallest over its largest entry",
          "[stress]") {
  // K = diag(4, 9, 1, 16, 25, 2.25) in two nodes of three: L = sqrt(K), pivots L_ii^2 = K_ii.
  const std::vector<double> d = {4, 9, 1, 16, 25, 2.25};
  Eigen::SparseMatrix<double> k(6, 6);
  for (int i = 0; i < 6; ++i) k.insert(i, i) = d[static_cast<std::size_t>(i)];
  k.makeCompressed();
  const std::vector<int> nodes = {0, 0, 0, 1, 1, 1};
  NodeBlockCholesky c;
  CHECK(c.pivot_ratio() == 0.0);  // nothing factorised yet
  REQUIRE(c.analyze(k, nodes));
  REQUIRE(c.factorize(k));
  CHECK(c.pivot_ratio() == Approx(1.0 / 25.0).epsilon(1e-15));
  const Eigen::VectorXd x = c.solve(Eigen::VectorXd::Ones(6));
  for (int i = 0; i < 6; ++i) CHECK(x[i] == Approx(1.0 / d[static_cast<std::size_t>(i)]).epsilon(1e-15));
}
