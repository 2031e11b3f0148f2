#pragma once
// The contact test of two convex hulls, as Bullet's convex-convex algorithm does it, with a separating
// axis kept per pair in front of it. Most pairs of a pile of pieces have overlapping bounding boxes but
// are apart; Bullet runs GJK on each of them every step. Here a pair without contact points first
// tries the axis that proved it apart last time, two scans of the hull points; when that fails, the
// line between the bodies' centres, then GJK, and the axis that works is kept. A pair's first test
// (an event's new pieces bring thousands at once) tries the centres' line only, then Bullet's test.
//
// The result is Bullet's own: a pair is skipped only when the hulls are proven apart by more than
// both margins plus the contact breaking threshold (a lower bound from the support scans, with a
// round-off allowance), and then Bullet's algorithm would add no contact point either (it drops every
// point beyond that threshold) and would only refresh an empty manifold. The manifold itself is made
// at the start of the pair's first test as Bullet's algorithm makes it there (or just before, by the
// dispatcher: make_hull_pair_manifold) and handed to it and kept, so the
// manifolds and their order, the solver's input, are the same: trajectories are identical bit for bit
// (tests/harness/pipeline/physics/hull_pair_collision_tests.cpp).

class btCollisionAlgorithm;
class btCollisionDispatcher;
class btCollisionObject;
class btDispatcher;

namespace shatter {

/// How often the pair test ran and what it saved, summed over a world's steps.
struct HullPairCounts {
  long tests = 0;    ///< hull-hull pair tests (every step, every pair with overlapping boxes)
  long skipped = 0;  ///< tests answered by a kept separating axis (no GJK)
  long probed = 0;   ///< tests where no kept axis answered and a new one (the centres' line or GJK's) proved the pair apart
  long first_apart = 0;  ///< of those, a pair's first test, answered by the centres' line (no GJK in that step)
};

/// Makes the contact manifold of a new pair of hulls `a` and `b` (in the pair's order) whose `algorithm`
/// is Bullet's convex-convex one or this test's, as the pair's first test would make it first thing,
/// and hands it to the algorithm: the first test itself can then run apart from the dispatcher's pools
/// (narrow_phase_dispatcher.h). Nothing when the algorithm has its manifold.
void make_hull_pair_manifold(btCollisionAlgorithm& algorithm, btDispatcher& dispatcher, const btCollisionObject* a,
                             const btCollisionObject* b);

/// The hull-hull pair test with kept separating axes, registered with a dispatcher for pairs of
/// btConvexHullShape (the children of compound shapes included). Owns what the registration points to;
/// keep it alive as long as the dispatcher.
class HullPairCollision {
 public:
  HullPairCollision();
  ~HullPairCollision();
  HullPairCollision(const HullPairCollision&) = delete;
  HullPairCollision& operator=(const HullPairCollision&) = delete;

  /// Makes `dispatcher` use this test for every new pair of hulls.
  void register_with(btCollisionDispatcher& dispatcher);
  /// The counts so far (safe to read between steps).
  [[nodiscard]] HullPairCounts counts() const;

 private:
  struct CreateFunc;
  CreateFunc* create_;
};

}  // namespace shatter
