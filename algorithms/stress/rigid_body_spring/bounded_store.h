#pragma once
/// A small store of entries kept between solves, oldest first, bounded in count and in bytes; the
/// analysis pool (analysis_pool.h) and the solved systems (solved_systems.h) of a solver each keep one.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace shatter {

/// `Entry` has a `std::size_t bytes` member: what it holds, counted against the byte bound.
template <class Entry>
class BoundedStore {
 public:
  BoundedStore(std::size_t max_entries, std::size_t max_bytes) : max_entries_(max_entries), max_bytes_(max_bytes) {}

  /// Removes and returns the first entry (oldest first) for which `match` holds; none when none does.
  template <class Match>
  std::optional<Entry> take(Match match) {
    const auto found = std::find_if(entries_.begin(), entries_.end(), match);
    if (found == entries_.end()) return std::nullopt;
    std::optional<Entry> out(std::move(*found));
    bytes_ -= out->bytes;
    entries_.erase(found);
    return out;
  }

  /// Adds `entry` unless it alone exceeds the byte bound (then `dropped` receives it). The oldest
  /// entries leave first, each through `dropped`, while the store is full in count or in bytes.
  template <class Dropped>
  void keep(Entry entry, Dropped dropped) {
    if (entry.bytes > max_bytes_) {
      dropped(entry);
      return;
    }
    while (!entries_.empty() && (entries_.size() >= max_entries_ || bytes_ + entry.bytes > max_bytes_)) {
      dropped(entries_.front());
      bytes_ -= entries_.front().bytes;
      entries_.erase(entries_.begin());
    }
    bytes_ += entry.bytes;
    entries_.push_back(std::move(entry));
  }

  std::size_t reuses = 0;  ///< entries handed out again (counted by the owner)

 private:
  std::size_t max_entries_, max_bytes_;
  std::vector<Entry> entries_;  // oldest first
  std::size_t bytes_ = 0;
};

}  // namespace shatter
