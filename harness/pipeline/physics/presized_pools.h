#pragma once
// Bullet's per-step arrays made at their peak size when the world is made.
//
// The first step after an event's pieces enter the world finds thousands of new pairs and contact
// points at once. Bullet keeps them in arrays that grow by doubling (each growth a fresh allocation,
// a copy, and first-touch page faults on the new memory), and it keeps their capacity from step to
// step, so the growth is paid once, inside the event's frame (docs/pipeline.md section 7: a quarter
// of the tower's event step). These classes make the arrays at a capacity given up front and touch
// their pages, moving that cost into the world's creation. Capacity only: every array is filled and
// read exactly as before, so every result is the same, bit for bit.

#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>

namespace shatter {

/// The sequential-impulse solver with room for `contacts` contact constraints and as many friction
/// constraints (one per contact point, Bullet's default solver mode) from the start.
class PresizedSolver final : public btSequentialImpulseConstraintSolver {
 public:
  explicit PresizedSolver(int contacts);
};

/// The hashed pair cache with room for `pairs` overlapping pairs (rounded up to a power of two, the
/// capacities Bullet's doubling reaches, which its hash masks with) and its hash table at that size.
class PresizedPairCache final : public btHashedOverlappingPairCache {
 public:
  explicit PresizedPairCache(int pairs);
};

}  // namespace shatter
