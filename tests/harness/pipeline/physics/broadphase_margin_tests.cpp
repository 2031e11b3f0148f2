// PhysicsSettings::broadphase_margin: the growth of a moving body's box in Bullet's bounding-volume
// tree. A smaller one makes fewer pairs and the same contacts; the world leaves Bullet's process-wide
// value as it found it.

#include "harness/pipeline/physics/physics_world.h"
#include "tests/support/standing_block.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <catch2/catch.hpp>

#include <vector>

using shatter::Fragment;
using shatter::PhysicsSettings;
using shatter::test::SteppedBlock;
using shatter::test::largest_difference;
using shatter::test::stand_block;

TEST_CASE("broadphase margin: fewer pairs, the same contacts, trajectories as close as another body order",
          "[physics]") {
  // The block of 60 slabs of standing_block.h, one knocked. Every box moves in the first step (the
  // bodies start falling under gravity), so every box in the tree is grown by the margin then: Bullet's
  // 0.05 m makes pairs of slabs a few centimetres apart, 0.01 m fewer. The first step's contacts are
  // found before anything has moved: the same touching pairs with the same numbers of points. Then the
  // solver meets the contacts in another order (fewer pairs, other islands), and positions differ as
  // they do when Bullet gets the same bodies in another order: the yardstick.
  const std::vector<Fragment> slabs = shatter::test::block_slices();
  PhysicsSettings bullets;
  bullets.broadphase_margin = 0.05;  // Bullet's own gDbvtMargin
  PhysicsSettings small;
  small.broadphase_margin = 0.01;
  for (const int steps : {1, 30}) {
    const SteppedBlock wide = stand_block(slabs, bullets, false, steps);
    const SteppedBlock narrow = stand_block(slabs, small, false, steps);
    const SteppedBlock reordered = stand_block(slabs, bullets, true, steps);
    const double by_margin = largest_difference(wide.positions, narrow.positions);
    const double by_order = largest_difference(wide.positions, reordered.positions);
    INFO(steps << " steps: pairs with 0.05 m " << wide.pairs << ", with 0.01 m " << narrow.pairs
               << "; largest difference from the margin " << by_margin << " m, from the order " << by_order
               << " m");
    CHECK(narrow.pairs < wide.pairs);
    if (steps == 1) {
      REQUIRE(wide.touching.size() > 100);  // the block stands in contact, not apart
      CHECK(wide.touching == narrow.touching);
      CHECK(wide.touching == reordered.touching);
    }
    CHECK(by_margin <= 2.0 * by_order);
    CHECK(by_order > 0.0);
  }
}

TEST_CASE("broadphase margin: a step leaves Bullet's process-wide margin as it was", "[physics]") {
  const btScalar before = gDbvtMargin;
  PhysicsSettings s;
  s.broadphase_margin = 0.003;
  REQUIRE(static_cast<double>(before) != s.broadphase_margin);
  const std::vector<Fragment> slabs = shatter::test::block_slices();
  const SteppedBlock stepped = stand_block(slabs, s, false, 2);
  CHECK(stepped.pairs > 0);
  CHECK(gDbvtMargin == before);
}
