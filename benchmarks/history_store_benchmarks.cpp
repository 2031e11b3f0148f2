// The history store at scale (docs/history.md, "Scale"): a store of 1,000 commits, each with one run
// of 50 cells x 10 stages x 4 metrics (2,000 series) x 5 samples, 10 M samples in all, made once per
// backend before the first row (not timed). Rows: recording one more run, `history changes` over
// every series, `history show` of one case (the command, as a child process, its output dropped;
// and the store's queries with the analysis, in this process), on SQLite (a file under the build's
// temporary folder) and, when SHATTER_BENCH_POSTGRES names a server, on PostgreSQL:
//
//   scripts/postgres-test-server start build/pg-bench
//   SHATTER_BENCH_POSTGRES=$(cat build/pg-bench/url) build/bin/shatter_benchmarks --benchmark_filter=history_store
//
// Counters: `file_mb` (the SQLite file, WAL checkpointed), `series`, `samples`.
#include "harness/history/series_points.h"
#include "harness/history/store/history_store.h"
#include "harness/process/child_process.h"

#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#ifndef SHATTER_CLI
#error "the history store benchmarks need SHATTER_CLI (a compile definition of the benchmark target)"
#endif

namespace {

using namespace shatter;
namespace fs = std::filesystem;

constexpr int kCommits = 1000, kCells = 50, kStages = 10, kMetrics = 4, kSamples = 5;
constexpr const char* kMetricNames[kMetrics] = {"time_ms", "cpu_ms", "instructions", "volume_error"};

/// Run `c` of the synthetic history: level 1 + 0.1 x the stage, a 10 % step of every fifth cell at
/// commit 600, 2 % noise.
RunRecord scale_run(int c, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 0.02);
  RunRecord run;
  run.id = fmt::format("scale-run-{:06d}", c);
  run.commit = CommitInfo{fmt::format("{:040x}", 0x5ca1e000000ULL + static_cast<unsigned long long>(c)), {}, "main",
                          false, 1767225600 + 3600LL * c};
  run.kind = "grid";
  run.case_name = "scale";
  run.fingerprint = "0123456789abcdef";
  run.machine = "bench";
  run.source = run.id + ".json";
  run.context_json = "{}";
  run.settings_json = "{}";
  for (int cell = 0; cell < kCells; ++cell)
    for (int stage = 0; stage < kStages; ++stage)
      for (int m = 0; m < kMetrics; ++m) {
        const double level = (1.0 + 0.1 * stage) * (cell % 5 == 0 && c >= 600 ? 1.1 : 1.0);
        Measurement meas{SeriesKey{"grid", "scale", run.fingerprint, fmt::format("{} x 25 plane-slice", 10 + cell),
                                   fmt::format("stage s{}", stage), kMetricNames[m], m == 3 ? "" : "ms", Better::lower},
                         {}};
        for (int s = 0; s < kSamples; ++s) meas.samples.push_back(level * (1.0 + noise(rng)));
        run.measurements.push_back(std::move(meas));
      }
  return run;
}

/// The store of `location`, filled once per process.
HistoryStore& scale_store(const std::string& location) {
  static std::map<std::string, HistoryStore> stores;
  auto it = stores.find(location);
  if (it != stores.end()) return it->second;
  if (!location.starts_with("postgresql://")) fs::remove(location), fs::remove(location + "-wal"), fs::remove(location + "-shm");
  Result<HistoryStore> opened = HistoryStore::open(location, StoreOptions{true, 60.0});
  if (!opened) throw std::runtime_error(opened.error().message);
  if (location.starts_with("postgresql://"))
    for (const char* t : {"sb_acknowledgements", "sb_measurements", "sb_series", "sb_runs", "sb_commits"})
      (void)opened->connection().query(fmt::format("DELETE FROM {}", t));
  std::mt19937_64 rng(42);
  for (int c = 0; c < kCommits; ++c)
    if (Result<bool> r = opened->record(scale_run(c, rng)); !r) throw std::runtime_error(r.error().message);
  return stores.emplace(location, std::move(*opened)).first->second;
}

std::string sqlite_location() { return (fs::temp_directory_path() / "shatter_history_scale.sqlite").string(); }

std::string postgres_location() {
  const char* url = std::getenv("SHATTER_BENCH_POSTGRES");
  return url != nullptr ? url : "";
}

void counters(benchmark::State& state, const std::string& location) {
  state.counters["series"] = kCells * kStages * kMetrics;
  state.counters["samples"] = static_cast<double>(kCommits) * kCells * kStages * kMetrics * kSamples;
  if (!location.starts_with("postgresql://")) {
    std::error_code ec;
    state.counters["file_mb"] = static_cast<double>(fs::file_size(location, ec)) / 1e6;
  }
}

/// Runs the CLI with `args`, its output dropped; false when it did not exit 0.
bool cli(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {SHATTER_CLI};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildOptions o;
  o.stdout_file = "/dev/null";
  o.stderr_file = "/dev/null";
  Result<ChildExit> e = run_child(argv, o);
  return e && e->exited && e->code == 0;
}

template <class Body>
void on_backend(benchmark::State& state, bool postgres, Body body) {
  const std::string location = postgres ? postgres_location() : sqlite_location();
  if (location.empty()) {
    state.SkipWithError("SHATTER_BENCH_POSTGRES is not set (see the file's comment)");
    return;
  }
  try {
    HistoryStore& store = scale_store(location);
    body(state, store, location);
    counters(state, location);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

void history_store_record_run(benchmark::State& state, bool postgres) {
  on_backend(state, postgres, [](benchmark::State& st, HistoryStore& store, const std::string&) {
    std::mt19937_64 rng(7);
    static int next = kCommits;
    for (auto _ : st) {
      st.PauseTiming();
      RunRecord run = scale_run(next++, rng);
      st.ResumeTiming();
      if (Result<bool> r = store.record(run); !r || !*r) st.SkipWithError(r ? "not recorded" : r.error().message.c_str());
    }
  });
}

void history_store_changes_all(benchmark::State& state, bool postgres) {
  on_backend(state, postgres, [](benchmark::State& st, HistoryStore& store, const std::string&) {
    for (auto _ : st) {
      auto all = store.filtered_series_runs({});
      if (!all) st.SkipWithError(all.error().message.c_str());
      std::size_t steps = 0;
      for (const auto& [info, runs] : *all) steps += series_changes(commit_points(runs), info.key.better, {}).size();
      benchmark::DoNotOptimize(steps);
    }
  });
}

void history_store_changes_command(benchmark::State& state, bool postgres) {
  on_backend(state, postgres, [](benchmark::State& st, HistoryStore&, const std::string& location) {
    for (auto _ : st)
      if (!cli({"history", "changes", "--db", location})) st.SkipWithError("history changes failed");
  });
}

void history_store_show_command(benchmark::State& state, bool postgres) {
  on_backend(state, postgres, [](benchmark::State& st, HistoryStore&, const std::string& location) {
    for (auto _ : st)
      if (!cli({"history", "show", "--db", location, "--case", "scale"})) st.SkipWithError("history show failed");
  });
}

}  // namespace

BENCHMARK_CAPTURE(history_store_record_run, sqlite, false)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK_CAPTURE(history_store_changes_all, sqlite, false)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(history_store_changes_command, sqlite, false)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(history_store_show_command, sqlite, false)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(history_store_record_run, postgresql, true)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK_CAPTURE(history_store_changes_all, postgresql, true)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(history_store_changes_command, postgresql, true)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(history_store_show_command, postgresql, true)->Unit(benchmark::kMillisecond)->Iterations(3);
