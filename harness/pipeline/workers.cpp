#include "harness/pipeline/workers.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace shatter {

struct Workers::Arena {
  // oneTBB allows one thread per core by default and ignores a larger arena (with a warning on
  // stderr); the threads asked for are what runs, also beyond the machine's cores.
  explicit Arena(int threads)
      : allowed(tbb::global_control::max_allowed_parallelism,
                std::max<std::size_t>(static_cast<std::size_t>(threads),
                                      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))),
        arena(threads) {}
  tbb::global_control allowed;
  tbb::task_arena arena;
};

Workers::Workers(int threads) : threads_(std::clamp(threads, 1, kMaxWorkerThreads)) {
  if (threads_ > 1) arena_ = std::make_unique<Arena>(threads_);
}

Workers::~Workers() = default;

void Workers::for_each(std::size_t count, const std::function<void(std::size_t)>& task) {
  if (!arena_ || count < 2) {
    for (std::size_t i = 0; i < count; ++i) task(i);
    return;
  }
  // One index per task: the tasks here are whole fractures and hulls, far larger than a task's cost.
  arena_->arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) task(i);
        },
        tbb::simple_partitioner());
  });
}

}  // namespace shatter
