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
    shatter::test::check_fewer_pairs_same_contacts(stand_block(slabs, bullets, false, steps),
                                                   stand_block(slabs, small, false, steps),
                                                   stand_block(slabs, bullets, true, steps), steps);
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
