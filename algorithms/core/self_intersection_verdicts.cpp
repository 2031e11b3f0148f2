#include "algorithms/core/self_intersection_verdicts.h"

#include <algorithm>

namespace shatter {

SelfIntersectionVerdicts::SelfIntersectionVerdicts(std::size_t capacity) : seen_(std::max<std::size_t>(capacity, 1), 0) {}

bool SelfIntersectionVerdicts::remembers(std::uint64_t fingerprint) const {
  const std::lock_guard lock(mutex_);
  const auto end = seen_.begin() + static_cast<std::ptrdiff_t>(count_);
  return std::find(seen_.begin(), end, fingerprint) != end;
}

void SelfIntersectionVerdicts::remember(std::uint64_t fingerprint) {
  const std::lock_guard lock(mutex_);
  seen_[next_] = fingerprint;
  next_ = (next_ + 1) % seen_.size();
  count_ = std::min(count_ + 1, seen_.size());
}

}  // namespace shatter
