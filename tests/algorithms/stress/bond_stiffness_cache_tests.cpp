// The kept bond stiffness (bond_stiffness_cache.h): each bond's spring, blocks and masks are those a
// direct computation gives, bit for bit, in whatever order and however often bonds are prepared, and a
// component solved with the cache gives the displacements and forces of one solved without it, bit for
// bit, on a planar wall (blocks with structural zeros) and on a box cut by oblique planes (dense blocks).
#include "algorithms/core/random.h"
#include "algorithms/stress/rigid_body_spring/bond_stiffness_cache.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/rigid_body_spring/stiffness_pattern.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <numeric>

using namespace shatter;
using namespace shatter::fixtures;

namespace {

bool same_bits(const void* a, const void* b, std::size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

bool same_bits(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return same_bits(a.data(), b.data(), sizeof(double) * 9); }

/// A 2.5 m cube anchored at its foot, cut by 12 random oblique planes: bonds whose blocks have no zeros.
SupportGraph oblique_box() {
  SplitMix64 random(11);
  std::vector<Plane> cuts;
  for (int i = 0; i < 12; ++i) {
    Plane p;
    p.point = Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(0, 2.5));
    p.normal = Vec3(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5)).normalized();
    cuts.push_back(p);
  }
  return graph_of(sliced_box({2.5, 2.5, 2.5}, {0.0, 0.0, 1.25}, cuts), {box_region({-2, -2, -0.1}, {2, 2, 0.1})}, 2400.0);
}

struct Solved {
  std::vector<double> displacements;
  std::vector<BondForces> forces;
  SolverReport report;
};

/// `g` under its own weight, solved as one component (every node, every bond), with or without `cache`.
Solved solve_whole(const SupportGraph& g, const Material& material, BondStiffnessCache* cache) {
  std::vector<int> nodes(g.nodes.size()), bonds(g.bonds.size());
  std::iota(nodes.begin(), nodes.end(), 0);
  std::iota(bonds.begin(), bonds.end(), 0);
  Solved out;
  out.displacements.assign(6 * g.nodes.size(), 0.0);
  out.forces.resize(g.bonds.size());
  SolverMemory memory;  // a new one per solve: nothing solved before is reused
  out.report = solve_component(g, nodes, bonds, node_loads(g, Loads{}, material), material, SpringSolverSettings{},
                               memory, out.displacements, out.forces, cache);
  return out;
}

}  // namespace

TEST_CASE("bond stiffness cache: every bond's spring, blocks and masks as computed directly, bit for bit",
          "[stress][local-cascade]") {
  const Material material;
  for (const SupportGraph& g : {block_wall(6, 5), oblique_box()}) {
    REQUIRE(g.bond_count() > 20);
    BondStiffnessCache cache(g, material);
    // Prepared in pieces, in reverse, some twice: the entries do not depend on the order of first use.
    std::vector<int> order(g.bonds.size());
    std::iota(order.rbegin(), order.rend(), 0);
    const std::span<const int> all(order);
    cache.prepare(all.subspan(0, all.size() / 2));
    cache.prepare(all.subspan(all.size() / 3));
    for (int b = 0; b < g.bond_count(); ++b) {
      const BondStiffness& kept = cache.at(b);
      const BondSpring spring = bond_spring(g, b, material);
      std::array<Matrix6, 4> blocks;
      bond_blocks(spring, blocks);
      CHECK(same_bits(kept.spring.translation, spring.translation));
      CHECK(same_bits(kept.spring.rotation, spring.rotation));
      CHECK(same_bits(kept.spring.lever_a.data(), spring.lever_a.data(), sizeof(double) * 3));
      CHECK(same_bits(kept.spring.lever_b.data(), spring.lever_b.data(), sizeof(double) * 3));
      for (std::size_t q = 0; q < 4; ++q) {
        CHECK(same_bits(kept.blocks[q].data(), blocks[q].data(), sizeof(double) * 36));
        CHECK(kept.masks[q] == nonzero_mask(blocks[q]));
      }
    }
  }
}

TEST_CASE("bond stiffness cache: a component solved with it gives what one solved without it gives, bit for bit",
          "[stress][local-cascade]") {
  const Material material;
  for (const SupportGraph& g : {block_wall(9, 7), oblique_box()}) {
    const Solved plain = solve_whole(g, material, nullptr);
    REQUIRE(plain.report.converged);
    REQUIRE(std::any_of(plain.displacements.begin(), plain.displacements.end(), [](double x) { return x != 0.0; }));
    BondStiffnessCache cache(g, material);
    for (int pass = 0; pass < 2; ++pass) {  // the first fills the cache, the second only reads it
      const Solved cached = solve_whole(g, material, &cache);
      CHECK(cached.report.converged);
      CHECK(cached.report.residual == plain.report.residual);
      CHECK(same_bits(cached.displacements.data(), plain.displacements.data(), sizeof(double) * plain.displacements.size()));
      CHECK(same_bits(cached.forces.data(), plain.forces.data(), sizeof(BondForces) * plain.forces.size()));
    }
  }
}
