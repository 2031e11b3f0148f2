#pragma once
// Bullet's collision dispatcher with the narrow phase of a step on worker threads. Debian's Bullet is
// built without BT_THREADSAFE, so its own multithreaded dispatcher runs serially; this one keeps
// Bullet's near callback and splits the pairs instead.
//
// Design note: what allocates stays on the calling thread, in Bullet's order. A pair's first test
// makes its collision algorithm and contact manifold (from the dispatcher's pools, appended to its
// manifold list, which sets the solver's order), and a compound's test makes and frees child
// algorithms. So the pairs are taken in Bullet's order once: a new pair of two hulls gets its
// algorithm and manifold made there, as Bullet's near callback and the pair's first test make them
// (make_hull_pair_manifold), and the tests of compounds and the ground run there; the others, pairs
// of two hulls that hold their manifold, each touching only its own manifold and algorithm, are then
// tested on the workers. The manifolds, their order and their contact points are those of the serial
// dispatch: trajectories are identical bit for bit on any number of threads
// (tests/harness/pipeline/physics/hull_pair_collision_tests.cpp).

#include <btBulletCollisionCommon.h>

#include <vector>

namespace shatter {

class Workers;

class NarrowPhaseDispatcher final : public btCollisionDispatcher {
 public:
  explicit NarrowPhaseDispatcher(btCollisionConfiguration* configuration) : btCollisionDispatcher(configuration) {}

  /// The threads of the next steps' narrow phase; none (or one thread) is Bullet's serial dispatch.
  void set_workers(Workers* workers) { workers_ = workers; }

  void dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                 btDispatcher* dispatcher) override;

 private:
  /// Makes the algorithm and manifold of a new pair of two hulls that needs a test.
  void prepare_first_test(btBroadphasePair& pair);

  Workers* workers_ = nullptr;
  std::vector<btBroadphasePair*> parallel_;  ///< this step's pairs for the workers
};

}  // namespace shatter
