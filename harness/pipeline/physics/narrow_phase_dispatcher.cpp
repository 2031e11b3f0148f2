#include "harness/pipeline/physics/narrow_phase_dispatcher.h"

#include "harness/pipeline/physics/hull_pair_collision.h"
#include "harness/pipeline/workers.h"

#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>

#include <algorithm>

namespace shatter {
namespace {

bool is_hull(const btBroadphaseProxy* proxy) {
  return static_cast<const btCollisionObject*>(proxy->m_clientObject)->getCollisionShape()->getShapeType() ==
         CONVEX_HULL_SHAPE_PROXYTYPE;
}

/// A pair whose test touches only its own algorithm and manifold: two hulls (Bullet's convex-convex
/// algorithm or the kept-axis one derived from it) whose manifold exists.
bool self_contained(const btBroadphasePair& pair) {
  if (pair.m_algorithm == nullptr || !is_hull(pair.m_pProxy0) || !is_hull(pair.m_pProxy1)) return false;
  return static_cast<btConvexConvexAlgorithm*>(pair.m_algorithm)->getManifold() != nullptr;
}

}  // namespace

void NarrowPhaseDispatcher::prepare_first_test(btBroadphasePair& pair) {
  if (pair.m_algorithm != nullptr || !is_hull(pair.m_pProxy0) || !is_hull(pair.m_pProxy1)) return;
  const auto* a = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
  const auto* b = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
  if (!needsCollision(a, b)) return;  // Bullet's near callback makes nothing for it either
  // What Bullet's near callback and the pair's first test make, in that order.
  const btCollisionObjectWrapper wa(nullptr, a->getCollisionShape(), a, a->getWorldTransform(), -1, -1);
  const btCollisionObjectWrapper wb(nullptr, b->getCollisionShape(), b, b->getWorldTransform(), -1, -1);
  pair.m_algorithm = findAlgorithm(&wa, &wb, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  if (pair.m_algorithm != nullptr) make_hull_pair_manifold(*pair.m_algorithm, *this, a, b);
}

void NarrowPhaseDispatcher::dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                                      btDispatcher* dispatcher) {
  if (workers_ == nullptr || workers_->threads() < 2 || info.m_dispatchFunc != btDispatcherInfo::DISPATCH_DISCRETE ||
      info.m_deterministicOverlappingPairs) {
    btCollisionDispatcher::dispatchAllCollisionPairs(pairs, info, dispatcher);
    return;
  }
  btNearCallback near = getNearCallback();
  // A new pair of hulls gets its algorithm and manifold here, so its first test can run on the workers
  // too (only when the near callback is Bullet's own, which is what makes them).
  const bool prepare = near == &btCollisionDispatcher::defaultNearCallback;
  const int count = pairs->getNumOverlappingPairs();
  btBroadphasePair* all = pairs->getOverlappingPairArrayPtr();
  parallel_.clear();
  for (int i = 0; i < count; ++i) {
    if (prepare) prepare_first_test(all[i]);
    if (self_contained(all[i]))
      parallel_.push_back(&all[i]);
    else
      near(all[i], *this, info);  // in Bullet's order: compounds, the ground
  }
  // A few chunks per thread: a pair's test is a few microseconds, a task's overhead about one.
  const std::size_t chunks =
      std::min(parallel_.size(), static_cast<std::size_t>(8 * workers_->threads()));
  workers_->for_each(chunks, [&](std::size_t chunk) {
    const std::size_t begin = parallel_.size() * chunk / chunks;
    const std::size_t end = parallel_.size() * (chunk + 1) / chunks;
    for (std::size_t k = begin; k < end; ++k) near(*parallel_[k], *this, info);
  });
}

}  // namespace shatter
