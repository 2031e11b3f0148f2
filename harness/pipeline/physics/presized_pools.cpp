#include "harness/pipeline/physics/presized_pools.h"

#include <algorithm>

namespace shatter {
namespace {

/// Makes `array` hold `n` elements, writing each (so its pages are in memory), then empties it: its
/// capacity stays.
template <class Array>
void make_room(Array& array, int n) {
  array.resize(std::max(n, 0));
  array.resize(0);
}

}  // namespace

PresizedSolver::PresizedSolver(int contacts) {
  make_room(m_tmpSolverContactConstraintPool, contacts);
  make_room(m_tmpSolverContactFrictionConstraintPool, contacts);
  make_room(m_orderTmpConstraintPool, contacts);
  make_room(m_orderFrictionConstraintPool, contacts);
}

PresizedPairCache::PresizedPairCache(int pairs) {
  int capacity = 2;  // the cache's own starting capacity
  while (capacity < pairs && capacity < (1 << 30)) capacity *= 2;
  // What the cache's growth does when its pair array reaches a new capacity, done here for an empty
  // cache: the hash table and the chain links at the capacity, every entry empty.
  getOverlappingPairArray().reserve(capacity);
  m_hashTable.resize(capacity, BT_NULL_PAIR);
  m_next.resize(capacity, BT_NULL_PAIR);
}

}  // namespace shatter
