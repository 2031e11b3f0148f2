#pragma once
/// A block of plane-sliced slabs standing on the ground with one knocked: a physics scene of many
/// hulls in contact, for tests that compare a collider or broadphase setting with Bullet's own spread
/// (the same bodies added in another order).

#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/pipeline/physics/physics_world.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>
#include <vector>

namespace shatter::test {

/// A 2 x 1 x 1 m block on z = 0 cut into 60 slabs by plane slicing (seed 11): neighbours share faces,
/// and later cuts leave points on the earlier pieces' edges.
inline std::vector<Fragment> block_slices() {
  FractureParams params;
  params.fragments = 60;
  params.seed = 11;
  auto out = PlaneSliceFracturer().fracture(make_box(Vec3(2, 1, 1), Vec3(0, 0, 0.5)), params);
  REQUIRE(out.ok());
  return std::move(*out);
}

struct SteppedBlock {
  std::vector<TouchingPair> touching;  ///< sorted, named by slab
  std::vector<Vec3> positions;         ///< by slab
  int pairs = 0;                       ///< most overlapping pairs of boxes in a step
};

/// The slabs standing on the ground (`settings` with the ground on), slab 7 knocked, after `steps`
/// steps; bodies added in reverse order when `reversed`.
inline SteppedBlock stand_block(const std::vector<Fragment>& slabs, PhysicsSettings settings, bool reversed, int steps) {
  settings.ground = true;
  PhysicsWorld world(settings);
  std::vector<int> ids(slabs.size());
  for (std::size_t k = 0; k < slabs.size(); ++k) {
    const std::size_t i = reversed ? slabs.size() - 1 - k : k;
    ids[i] = world.add_fragment(slabs[i], 2400.0);
  }
  world.apply_impulse(ids[7], Vec3(50, 20, 0), slabs[7].mass.centroid);
  SteppedBlock out;
  for (int i = 0; i < steps; ++i) {
    world.step();
    out.pairs = std::max(out.pairs, world.overlapping_pairs());
  }
  out.touching = world.touching_pairs();
  if (reversed)  // ids were given in reverse: name the pairs by slab
    for (TouchingPair& p : out.touching) {
      const auto slab = [&](int id) { return id < 0 ? id : static_cast<int>(slabs.size()) - 1 - id; };
      p = {std::min(slab(p.first), slab(p.second)), std::max(slab(p.first), slab(p.second)), p.points};
    }
  std::sort(out.touching.begin(), out.touching.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first, a.second) < std::tie(b.first, b.second);
  });
  for (const int id : ids) out.positions.push_back(world.position(id));
  return out;
}

inline double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

/// The checks of a setting that should make fewer pairs and the same contacts, after `steps` steps:
/// `bullets` with Bullet's own setting, `changed` with the setting, `reordered` with Bullet's setting
/// and the bodies added in reverse. Fewer pairs; after one step (before anything moved) the same
/// touching pairs and contact points; positions no farther from Bullet's than twice the spread that
/// the body order alone makes.
inline void check_fewer_pairs_same_contacts(const SteppedBlock& bullets, const SteppedBlock& changed,
                                            const SteppedBlock& reordered, int steps) {
  const double by_setting = largest_difference(bullets.positions, changed.positions);
  const double by_order = largest_difference(bullets.positions, reordered.positions);
  INFO(steps << " steps: pairs with Bullet's setting " << bullets.pairs << ", with the change " << changed.pairs
             << "; largest difference from the change " << by_setting << " m, from the order " << by_order << " m");
  CHECK(changed.pairs < bullets.pairs);
  if (steps == 1) {
    REQUIRE(bullets.touching.size() > 100);  // the block stands in contact, not apart
    CHECK(bullets.touching == changed.touching);
    CHECK(bullets.touching == reordered.touching);
  }
  CHECK(by_setting <= 2.0 * by_order);
  CHECK(by_order > 0.0);
}

}  // namespace shatter::test
