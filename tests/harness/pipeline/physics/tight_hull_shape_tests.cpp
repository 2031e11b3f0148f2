// TightHullShape's box is the exact world box of the hull's points plus its margin; with it the
// broadphase finds fewer pairs and the narrow phase the same contacts.

#include "harness/pipeline/physics/physics_world.h"
#include "harness/pipeline/physics/tight_hull_shape.h"
#include "tests/support/standing_block.h"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using shatter::Fragment;
using shatter::PhysicsSettings;
using shatter::test::stand_block;

TEST_CASE("tight hull: the box holds every point plus the margin and touches the extreme ones", "[physics]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  shatter::TightHullShape tight;
  btConvexHullShape loose;
  for (int i = 0; i < 40; ++i) {
    const btVector3 p(btScalar(3 * u(rng)), btScalar(0.2 * u(rng)), btScalar(u(rng)));  // a slab
    tight.addPoint(p, false);
    loose.addPoint(p, false);
  }
  tight.recalcLocalAabb();
  loose.recalcLocalAabb();
  tight.setMargin(0.01f);
  loose.setMargin(0.01f);
  for (int trial = 0; trial < 50; ++trial) {
    const btQuaternion q(btVector3(btScalar(u(rng)), btScalar(u(rng)), btScalar(u(rng))).normalized(),
                         btScalar(3.0 * u(rng)));
    const btTransform t(q, btVector3(btScalar(40 * u(rng)), btScalar(40 * u(rng)), btScalar(5 * u(rng))));
    btVector3 lo, hi, loose_lo, loose_hi;
    tight.getAabb(t, lo, hi);
    loose.getAabb(t, loose_lo, loose_hi);
    for (int k = 0; k < 3; ++k) {
      double low = HUGE_VAL, high = -HUGE_VAL;
      for (int i = 0; i < tight.getNumPoints(); ++i) {
        const btVector3 w = t(tight.getUnscaledPoints()[i]);
        low = std::min(low, double(w[k]));
        high = std::max(high, double(w[k]));
      }
      CHECK(lo[k] <= low - 0.01);
      CHECK(hi[k] >= high + 0.01);
      CHECK(lo[k] >= low - 0.01 - 1e-3);  // no looser than a millimetre of round-off allowance
      CHECK(hi[k] <= high + 0.01 + 1e-3);
      CHECK(lo[k] >= loose_lo[k] - 1e-4f);  // never larger than Bullet's own
      CHECK(hi[k] <= loose_hi[k] + 1e-4f);
    }
  }
}

TEST_CASE("tight hull: fewer pairs, the same contacts, trajectories as close as another body order", "[physics]") {
  // A block of 60 slabs standing on the ground, neighbours sharing faces, one knocked. The first step's
  // contacts are found before anything moves: both boxes give the same touching pairs with the same
  // numbers of points. The solver then meets them in another order; its fixed iterations do not
  // converge on a stack, so positions differ, as they do in Bullet's own world when the same bodies
  // are added in another order: the yardstick here.
  const std::vector<Fragment> slabs = shatter::test::block_slices();
  PhysicsSettings loose_boxes;
  loose_boxes.tight_bounds = false;
  PhysicsSettings tight_boxes;
  tight_boxes.tight_bounds = true;
  for (const int steps : {1, 30}) {
    shatter::test::check_fewer_pairs_same_contacts(stand_block(slabs, loose_boxes, false, steps),
                                                   stand_block(slabs, tight_boxes, false, steps),
                                                   stand_block(slabs, loose_boxes, true, steps), steps);
  }
}
