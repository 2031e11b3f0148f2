// TightHullShape's box is the exact world box of the hull's points plus its margin; with it the
// broadphase finds fewer pairs and the narrow phase the same contacts.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/pipeline/physics/physics_world.h"
#include "harness/pipeline/physics/tight_hull_shape.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <tuple>
#include <vector>

namespace {

using shatter::Fragment;
using shatter::PhysicsSettings;
using shatter::PhysicsWorld;
using shatter::Vec3;

std::vector<Fragment> block_slices() {
  shatter::FractureParams params;
  params.fragments = 60;
  params.seed = 11;
  auto out = shatter::PlaneSliceFracturer().fracture(shatter::make_box(Vec3(2, 1, 1), Vec3(0, 0, 0.5)), params);
  REQUIRE(out.ok());
  return std::move(*out);
}

}  // namespace

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

namespace {

struct Stepped {
  std::vector<shatter::TouchingPair> touching;
  std::vector<Vec3> positions;  ///< by slab
  int pairs = 0;
};

/// The slabs standing on the ground, one knocked, after `steps` steps; bodies added in reverse order
/// when `reversed` (the same scene, another order of Bullet's pairs and contacts).
Stepped stand_block(const std::vector<Fragment>& slabs, bool tight, bool reversed, int steps) {
  PhysicsSettings s;
  s.ground = true;
  s.tight_bounds = tight;
  PhysicsWorld world(s);
  std::vector<int> ids(slabs.size());
  for (std::size_t k = 0; k < slabs.size(); ++k) {
    const std::size_t i = reversed ? slabs.size() - 1 - k : k;
    ids[i] = world.add_fragment(slabs[i], 2400.0);
  }
  world.apply_impulse(ids[7], Vec3(50, 20, 0), slabs[7].mass.centroid);
  Stepped out;
  for (int i = 0; i < steps; ++i) {
    world.step();
    out.pairs = std::max(out.pairs, world.overlapping_pairs());
  }
  out.touching = world.touching_pairs();
  if (reversed)  // ids were given in reverse: name the pairs by slab
    for (shatter::TouchingPair& p : out.touching) {
      const auto slab = [&](int id) { return id < 0 ? id : static_cast<int>(slabs.size()) - 1 - id; };
      p = {std::min(slab(p.first), slab(p.second)), std::max(slab(p.first), slab(p.second)), p.points};
    }
  std::sort(out.touching.begin(), out.touching.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first, a.second) < std::tie(b.first, b.second);
  });
  for (const int id : ids) out.positions.push_back(world.position(id));
  return out;
}

double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

}  // namespace

TEST_CASE("tight hull: fewer pairs, the same contacts, trajectories as close as another body order", "[physics]") {
  // A block of 60 slabs standing on the ground, neighbours sharing faces, one knocked. The first step's
  // contacts are found before anything moves: both boxes give the same touching pairs with the same
  // numbers of points. The solver then meets them in another order; its fixed iterations do not
  // converge on a stack, so positions differ, as they do in Bullet's own world when the same bodies
  // are added in another order: the yardstick here.
  const std::vector<Fragment> slabs = block_slices();
  for (const int steps : {1, 30}) {
    const Stepped loose = stand_block(slabs, false, false, steps);
    const Stepped tight = stand_block(slabs, true, false, steps);
    const Stepped reordered = stand_block(slabs, false, true, steps);
    const double by_boxes = largest_difference(loose.positions, tight.positions);
    const double by_order = largest_difference(loose.positions, reordered.positions);
    INFO(steps << " steps: pairs with Bullet's boxes " << loose.pairs << ", with exact boxes " << tight.pairs
               << "; largest difference from the boxes " << by_boxes << " m, from the order " << by_order << " m");
    CHECK(tight.pairs < loose.pairs);
    if (steps == 1) {
      REQUIRE(loose.touching.size() > 100);  // the block stands in contact, not apart
      CHECK(loose.touching == tight.touching);
      CHECK(loose.touching == reordered.touching);
    }
    CHECK(by_boxes <= 2.0 * by_order);
    CHECK(by_order > 0.0);
  }
}
