#pragma once
/// Worker threads for the independent parts of a runtime event: the fractures of different hit
/// fragments and the colliders of different pieces (docs/pipeline.md section 7). A oneTBB arena of a
/// fixed number of threads; one thread runs every task on the calling thread, in order, with no
/// arena at all (the seed's single-threaded comparison).
///
/// Design note: every task writes only its own slot of an output the caller sized before, and the
/// caller takes the results in index order afterwards, so a run's results do not depend on the number
/// of threads or on which thread ran which task.

#include <cstddef>
#include <functional>
#include <memory>

namespace shatter {

/// Most worker threads a run may use.
inline constexpr int kMaxWorkerThreads = 64;

/// A fixed number of threads that run indexed tasks.
class Workers {
 public:
  /// `threads` in 1..kMaxWorkerThreads (the caller checks; outside it is clamped).
  explicit Workers(int threads = 1);
  ~Workers();
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;

  /// The number of threads tasks run on (the calling thread included).
  [[nodiscard]] int threads() const { return threads_; }

  /// Runs `task(i)` for every i in [0, count) and returns when all have run: with one thread in
  /// order on the calling thread, otherwise on up to threads() threads in any order. An exception a
  /// task throws reaches the caller (with several threads, one of them, after the others stopped).
  void for_each(std::size_t count, const std::function<void(std::size_t)>& task);

 private:
  struct Arena;
  int threads_ = 1;
  std::unique_ptr<Arena> arena_;  // none for one thread
};

}  // namespace shatter
