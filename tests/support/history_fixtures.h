#pragma once
/// What the history tests record: grid results files made from known numbers, git repositories
/// with commits at known times, and fresh stores (an SQLite file, or a schema of its own on the test
/// PostgreSQL server).

#include "algorithms/core/random.h"
#include "harness/process/child_process.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/run_context.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace shatter::test {

/// A fresh scratch folder for one test (removed and made again).
inline std::filesystem::path history_scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_history_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The context every synthetic results file carries (one fingerprint: one set of series).
inline RunContext history_context(const std::string& commit) {
  RunContext c;
  c.commit = commit;
  c.build_type = "Release";
  c.compiler = "GNU 12.2.0";
  c.flags = "-O3 -DNDEBUG";
  c.cpu_model = "Example CPU";
  c.cores = 2;
  c.date = "2026-12-01T07:00:00Z";
  c.hostname = "runner";
  c.fingerprint = context_fingerprint(c);
  return c;
}

/// A grid results file of `cells` cells of `repetitions` repetitions: worst frame 3 ms, stress 1 ms and
/// physics 1.2 ms, each times `scale` times a noise factor in [1 - noise, 1 + noise] (SplitMix64 `seed`).
inline std::string synthetic_grid_text(double scale, double noise, std::uint64_t seed, const std::string& commit,
                                       int cells = 2, int repetitions = 5, double budget_ms = 33.3) {
  GridResult g;
  g.budget_ms = budget_ms;
  g.repetitions = repetitions;
  g.frames = 4;
  g.same_seed = true;
  SplitMix64 rng(seed);
  for (int p = 0; p < cells; ++p) {
    GridCell c;
    c.prefracture = 10 * (p + 1);
    c.runtime = 25;
    c.prefracturer = c.fracturer = "plane-slice";
    c.stress = "von-mises";
    c.stages_run = {"stress", "physics"};
    for (int k = 0; k < repetitions; ++k) {
      GridSample s;
      s.seed = static_cast<std::uint64_t>(k + 1);
      const double f = scale * (1.0 + noise * (2.0 * rng.uniform() - 1.0));
      s.frame_ms = {0.3 * f, 3.0 * f, 0.4 * f, 0.35 * f};
      s.worst_frame_ms = 3.0 * f;
      s.event_ms = 3.0 * f;
      s.event_frame = 1;
      s.stages_ms[static_cast<std::size_t>(Stage::stress)] = 1.0 * f;
      s.stages_ms[static_cast<std::size_t>(Stage::physics)] = 1.2 * f;
      s.worst_frame_cpu_ms = 2.9 * f;
      s.stages_cpu_ms = s.stages_ms;
      c.samples.push_back(s);
    }
    c.worst_frame_ms = 3.0 * scale;
    c.within_budget = c.worst_frame_ms <= budget_ms;
    g.cells.push_back(c);
  }
  const nlohmann::ordered_json case_block = {{"name", "synthetic"}};
  return grid_to_json(g, case_block, history_context(commit)).dump(2);
}

/// Writes `text` to `path` and returns the path.
inline std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// Runs git in `repo` (an argument vector: no shell), requiring success; its output.
inline std::string git_in(const std::filesystem::path& repo, std::vector<std::string> args) {
  args.insert(args.begin(), "git");
  Result<ChildOutput> r = run_child_output(args, repo);
  REQUIRE(r);
  INFO(r->err);
  REQUIRE(r->exit.exited);
  REQUIRE(r->exit.code == 0);
  std::string out = r->out;
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

/// A git repository in `dir` with `count` empty commits, one a day from 2026-01-01 (or all in one
/// second when `one_second`, as a rebased stack is); their shas in order.
inline std::vector<std::string> make_commits(const std::filesystem::path& dir, int count, bool one_second = false) {
  std::filesystem::create_directories(dir);
  git_in(dir, {"init", "-q", "-b", "main"});
  std::vector<std::string> shas;
  for (int i = 0; i < count; ++i) {
    // The committer time orders the history; git reads it from the environment only.
    const std::string when = std::to_string(1767225600 + (one_second ? 0 : 86400LL * i)) + " +0000";
    ::setenv("GIT_COMMITTER_DATE", when.c_str(), 1);
    git_in(dir, {"-c", "user.name=t", "-c", "user.email=t@example.org", "commit", "-q", "--allow-empty",
                 "--date=" + when, "-m", "c" + std::to_string(i)});
    shas.push_back(git_in(dir, {"rev-parse", "HEAD"}));
  }
  ::unsetenv("GIT_COMMITTER_DATE");
  return shas;
}

}  // namespace shatter::test
