#include "harness/pipeline/physics/hull_pair_collision.h"

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <LinearMath/btPoolAllocator.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>

namespace shatter {
namespace {

/// The largest of d . p over the hull's points (scaled as the shape scales them), in double.
double highest_along(const btConvexHullShape& hull, const btVector3& local_dir) {
  const btVector3 d = local_dir * hull.getLocalScaling();
  const double dx = d.x(), dy = d.y(), dz = d.z();
  const btVector3* p = hull.getUnscaledPoints();
  const int n = hull.getNumPoints();
  double high = -HUGE_VAL;
  for (int i = 0; i < n; ++i) high = std::max(high, dx * p[i].x() + dy * p[i].y() + dz * p[i].z());
  return high;
}

/// The gap between the two hulls along the unit world axis `n` (from a towards b): min over b of n . x
/// less max over a of n . x. A lower bound of their distance whenever it is positive.
double gap_along(const btConvexHullShape& a, const btTransform& ta, const btConvexHullShape& b,
                 const btTransform& tb, const btVector3& n) {
  const double a_high = highest_along(a, n * ta.getBasis()) + n.dot(ta.getOrigin());
  const double b_low = -highest_along(b, -n * tb.getBasis()) + n.dot(tb.getOrigin());
  return b_low - a_high;
}

double largest_coordinate(const btVector3& v) {
  return std::max({std::abs(static_cast<double>(v.x())), std::abs(static_cast<double>(v.y())),
                   std::abs(static_cast<double>(v.z()))});
}

/// A GJK result sink: the probe wants the separating axis only.
struct DiscardResult final : btDiscreteCollisionDetectorInterface::Result {
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar) override {}
};

/// The counts of HullPairCounts, kept by the tests of pairs on any thread (a step's narrow phase can run
/// on workers: narrow_phase_dispatcher.h).
struct SharedCounts {
  std::atomic<long> tests{0};
  std::atomic<long> skipped{0};
  std::atomic<long> probed{0};
  std::atomic<long> first_apart{0};
};

// Bullet's convex-convex algorithm makes its pair's contact manifold at the start of the pair's first
// test, in members it keeps private. To answer a first test without GJK, the manifold is made here at
// that same point, the same way, and handed to those members, so that Bullet finds afterwards what it
// would have made itself. The members are reached by naming them in an explicit instantiation, where
// the language does not check access.
template <class Tag, typename Tag::type Member>
struct PrivateMember {
  friend typename Tag::type member_of(Tag) { return Member; }
};
struct ManifoldPtrOf {
  using type = btPersistentManifold* btConvexConvexAlgorithm::*;
  friend type member_of(ManifoldPtrOf);
};
struct OwnsManifoldOf {
  using type = bool btConvexConvexAlgorithm::*;
  friend type member_of(OwnsManifoldOf);
};
template struct PrivateMember<ManifoldPtrOf, &btConvexConvexAlgorithm::m_manifoldPtr>;
template struct PrivateMember<OwnsManifoldOf, &btConvexConvexAlgorithm::m_ownManifold>;

}  // namespace

void make_hull_pair_manifold(btCollisionAlgorithm& algorithm, btDispatcher& dispatcher, const btCollisionObject* a,
                             const btCollisionObject* b) {
  auto& convex = static_cast<btConvexConvexAlgorithm&>(algorithm);
  if (convex.getManifold() != nullptr) return;
  convex.*member_of(ManifoldPtrOf{}) = dispatcher.getNewManifold(a, b);
  convex.*member_of(OwnsManifoldOf{}) = true;
}

namespace {

class HullPairAlgorithm final : public btConvexConvexAlgorithm {
 public:
  HullPairAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* w0,
                    const btCollisionObjectWrapper* w1, const btConvexConvexAlgorithm::CreateFunc& bullet,
                    SharedCounts& counts)
      : btConvexConvexAlgorithm(ci.m_manifold, ci, w0, w1, bullet.m_pdSolver, bullet.m_numPerturbationIterations,
                                bullet.m_minimumPointsPerturbationThreshold),
        counts_(counts) {}

  void processCollision(const btCollisionObjectWrapper* w0, const btCollisionObjectWrapper* w1,
                        const btDispatcherInfo& info, btManifoldResult* out) override {
    counts_.tests.fetch_add(1, std::memory_order_relaxed);
    const bool first = !tested_;
    tested_ = true;
    // What Bullet's test does first: make the pair's manifold (unless the dispatcher made it already).
    make_hull_pair_manifold(*this, *m_dispatcher, w0->getCollisionObject(), w1->getCollisionObject());
    auto* manifold = const_cast<btPersistentManifold*>(getManifold());
    // A pair with contact points is near. On a first test only the centres' line is tried: a new pair
    // it does not separate often touches (an event's pieces start side by side), and then a GJK probe
    // would only precede Bullet's own.
    if (manifold->getNumContacts() == 0 && proven_apart(w0, w1, *manifold, *out, !first)) {
      if (first) counts_.first_apart.fetch_add(1, std::memory_order_relaxed);
      out->setPersistentManifold(manifold);  // what Bullet leaves behind for a pair beyond reach
      return;
    }
    btConvexConvexAlgorithm::processCollision(w0, w1, info, out);
  }

 private:
  /// True when the hulls are apart by more than both margins plus the manifold's contact breaking
  /// threshold (Bullet's reach for a contact point), proven along the kept axis, the centres' line or
  /// (with `gjk_probe`) GJK's.
  bool proven_apart(const btCollisionObjectWrapper* w0, const btCollisionObjectWrapper* w1,
                    const btPersistentManifold& manifold, const btManifoldResult& out, bool gjk_probe) {
    const auto& a = *static_cast<const btConvexHullShape*>(w0->getCollisionShape());
    const auto& b = *static_cast<const btConvexHullShape*>(w1->getCollisionShape());
    const btTransform& ta = w0->getWorldTransform();
    const btTransform& tb = w1->getWorldTransform();
    const double reach = static_cast<double>(a.getMargin()) + b.getMargin() + manifold.getContactBreakingThreshold() +
                         out.m_closestPointDistanceThreshold;
    // Bullet computes in btScalar: allow for its round-off at these coordinates before trusting a gap.
    const double scale = std::max({1.0, largest_coordinate(ta.getOrigin()), largest_coordinate(tb.getOrigin())});
    const double needed = reach + 1e-4 + 2e-5 * scale;
    if (has_axis_ && gap_along(a, ta, b, tb, axis_) > needed) {
      counts_.skipped.fetch_add(1, std::memory_order_relaxed);
      return true;
    }
    // The kept axis failed (or there is none yet): first the line between the two bodies' centres,
    // which separates most pairs of pieces that are apart, for two more scans.
    has_axis_ = false;
    const btVector3 centres = tb.getOrigin() - ta.getOrigin();
    if (centres.length2() > SIMD_EPSILON && keep_if_apart(centres.normalized(), a, ta, b, tb, needed)) return true;
    if (!gjk_probe) return false;
    // Then Bullet's GJK (no penetration solver: only its axis is wanted), which stops as soon as an
    // axis shows the pair beyond reach; check that axis exactly, either way round, and keep it.
    btVoronoiSimplexSolver simplex;
    btGjkPairDetector gjk(&a, &b, &simplex, nullptr);
    btGjkPairDetector::ClosestPointInput input;
    input.m_maximumDistanceSquared = static_cast<btScalar>(reach * reach);
    input.m_transformA = ta;
    input.m_transformB = tb;
    DiscardResult discard;
    gjk.getClosestPoints(input, discard, nullptr);
    const btVector3 v = gjk.getCachedSeparatingAxis();
    if (!(v.length2() > SIMD_EPSILON)) return false;
    const btVector3 n = v.normalized();
    return keep_if_apart(n, a, ta, b, tb, needed) || keep_if_apart(-n, a, ta, b, tb, needed);
  }

  /// Keeps the unit axis `n` (from a towards b) when the hulls' gap along it exceeds `needed`.
  bool keep_if_apart(const btVector3& n, const btConvexHullShape& a, const btTransform& ta,
                     const btConvexHullShape& b, const btTransform& tb, double needed) {
    if (!(gap_along(a, ta, b, tb, n) > needed)) return false;
    axis_ = n;
    has_axis_ = true;
    counts_.probed.fetch_add(1, std::memory_order_relaxed);
    return true;
  }

  SharedCounts& counts_;
  bool tested_ = false;     ///< a test ran: the next is not the pair's first
  btVector3 axis_{0, 0, 1};  ///< world, from the first body's hull towards the second's
  bool has_axis_ = false;
};

}  // namespace

struct HullPairCollision::CreateFunc final : btCollisionAlgorithmCreateFunc {
  const btConvexConvexAlgorithm::CreateFunc* bullet = nullptr;  ///< the configuration's own, for its settings
  int pool_element_size = 0;
  SharedCounts counts;

  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* w0,
                                                 const btCollisionObjectWrapper* w1) override {
    // The dispatcher's pool holds elements of the largest built-in algorithm; a larger one is
    // allocated apart (freeCollisionAlgorithm tells the two apart).
    constexpr int size = static_cast<int>(sizeof(HullPairAlgorithm));
    void* memory = size <= pool_element_size ? ci.m_dispatcher1->allocateCollisionAlgorithm(size)
                                             : btAlignedAlloc(sizeof(HullPairAlgorithm), 16);
    return new (memory) HullPairAlgorithm(ci, w0, w1, *bullet, counts);
  }
};

HullPairCollision::HullPairCollision() : create_(new CreateFunc) {}

HullPairCollision::~HullPairCollision() { delete create_; }

void HullPairCollision::register_with(btCollisionDispatcher& dispatcher) {
  btCollisionConfiguration* configuration = dispatcher.getCollisionConfiguration();
  create_->bullet = static_cast<const btConvexConvexAlgorithm::CreateFunc*>(
      configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE));
  create_->pool_element_size = configuration->getCollisionAlgorithmPool()->getElementSize();
  dispatcher.registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, create_);
}

HullPairCounts HullPairCollision::counts() const {
  return {create_->counts.tests.load(), create_->counts.skipped.load(), create_->counts.probed.load(),
          create_->counts.first_apart.load()};
}

}  // namespace shatter
