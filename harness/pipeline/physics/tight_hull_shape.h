#pragma once
// A convex hull whose bounding box is the exact box of its points in the world, not the world box of
// its local box. Bullet's btConvexHullShape keeps an axis-aligned box in its own frame and turns it
// with the body, so a slab lying at an angle gets a box many times its volume, and the broadphase
// pairs it with most of its neighbours (docs/pipeline.md section 7: the tower's event step, 24,488
// pairs, about 7,500 with exact boxes). Each pair costs a contact manifold and a narrow-phase test
// every step.
//
// The box still holds the hull, its collision margin and Bullet's contact threshold around it (added
// by Bullet as before), so every pair that can have a contact point is still found: a pair whose
// exact boxes are apart along an axis is apart by more than both margins plus that threshold.

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

namespace shatter {

class TightHullShape final : public btConvexHullShape {
 public:
  using btConvexHullShape::btConvexHullShape;
  /// The world box of the hull's points under `t`, grown by the margin (and a round-off allowance).
  void getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const override;
  /// Bullet's own sphere, from its local box as btConvexHullShape makes it: the sphere sets the contact
  /// breaking threshold of the shape's pairs, which the exact box must not change.
  void getBoundingSphere(btVector3& center, btScalar& radius) const override;
};

}  // namespace shatter
