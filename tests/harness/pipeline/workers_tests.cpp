// Worker threads (harness/pipeline/workers.h): every index runs exactly once on any number of
// threads, one thread runs them in order on the caller's thread, and a task's exception reaches the
// caller.

#include "harness/pipeline/workers.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace shatter;

TEST_CASE("workers: every index runs exactly once, on any number of threads", "[pipeline][threads]") {
  for (const int threads : {1, 2, 3, 8}) {
    Workers workers(threads);
    REQUIRE(workers.threads() == threads);
    for (const std::size_t count : {0U, 1U, 2U, 7U, 100U}) {
      std::vector<std::atomic<int>> runs(count);
      workers.for_each(count, [&](std::size_t i) { runs[i].fetch_add(1); });
      for (const auto& r : runs) REQUIRE(r.load() == 1);
    }
  }
}

TEST_CASE("workers: N threads run N tasks at once, also beyond the machine's cores", "[pipeline][threads]") {
  // Each task waits until all have started: only N threads at once let every task see all N arrive
  // (a deadline keeps a failure from hanging the suite).
  for (const int threads : {2, 3, 5}) {
    Workers workers(threads);
    std::atomic<int> arrived{0};
    std::atomic<int> saw_all{0};
    workers.for_each(static_cast<std::size_t>(threads), [&](std::size_t) {
      arrived.fetch_add(1);
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (arrived.load() < threads && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
      if (arrived.load() == threads) saw_all.fetch_add(1);
    });
    INFO("threads " << threads);
    REQUIRE(saw_all.load() == threads);
  }
}

TEST_CASE("workers: one thread runs the tasks in order on the calling thread", "[pipeline][threads]") {
  Workers workers(1);
  std::vector<std::size_t> order;
  const std::thread::id caller = std::this_thread::get_id();
  bool same_thread = true;
  workers.for_each(5, [&](std::size_t i) {
    order.push_back(i);
    same_thread = same_thread && std::this_thread::get_id() == caller;
  });
  REQUIRE(order == std::vector<std::size_t>{0, 1, 2, 3, 4});
  REQUIRE(same_thread);
}

TEST_CASE("workers: the thread count is kept within 1..kMaxWorkerThreads", "[pipeline][threads]") {
  REQUIRE(Workers(0).threads() == 1);
  REQUIRE(Workers(-3).threads() == 1);
  REQUIRE(Workers(kMaxWorkerThreads + 1).threads() == kMaxWorkerThreads);
}

TEST_CASE("workers: an exception thrown by a task reaches the caller", "[pipeline][threads]") {
  for (const int threads : {1, 2}) {
    Workers workers(threads);
    REQUIRE_THROWS_AS(workers.for_each(4,
                                       [](std::size_t i) {
                                         if (i == 2) throw std::runtime_error("task 2");
                                       }),
                      std::runtime_error);
    // The workers stay usable.
    std::atomic<int> done{0};
    workers.for_each(3, [&](std::size_t) { done.fetch_add(1); });
    REQUIRE(done.load() == 3);
  }
}
