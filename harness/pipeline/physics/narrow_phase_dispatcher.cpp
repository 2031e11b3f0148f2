#include "harness/pipeline/physics/narrow_phase_dispatcher.h"

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

void NarrowPhaseDispatcher::dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                                      btDispatcher* dispatcher) {
  if (workers_ == nullptr || workers_->threads() < 2 || info.m_dispatchFunc != btDispatcherInfo::DISPATCH_DISCRETE ||
      info.m_deterministicOverlappingPairs) {
    btCollisionDispatcher::dispatchAllCollisionPairs(pairs, info, dispatcher);
    return;
  }
  btNearCallback near = getNearCallback();
  const int count = pairs->getNumOverlappingPairs();
  btBroadphasePair* all = pairs->getOverlappingPairArrayPtr();
  parallel_.clear();
  for (int i = 0; i < count; ++i) {
    if (self_contained(all[i]))
      parallel_.push_back(&all[i]);
    else
      near(all[i], *this, info);  // in Bullet's order: the first test of a pair, compounds, the ground
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
