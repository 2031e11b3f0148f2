#include "harness/cases/case_library.h"
#include "harness/cli/command.h"
#include "harness/grid/grid_runner.h"
#include "harness/results/atomic_file.h"
#include "harness/results/grid_report.h"
#include "harness/results/run_context.h"

#include <fmt/core.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace shatter::cli {
namespace {

struct GridCommandOptions {
  std::string case_name;
  std::string fracturer;
  std::string stress;
  std::optional<double> budget_ms;
  int repetitions = 3;
  std::optional<int> frames;
  std::string json;
  std::vector<int> prefracture;
  std::vector<int> runtime;
  bool no_skip = false;
  std::string cache_dir;
  bool no_cache = false;
};

/// "cell k of N, elapsed, estimate" on one rewritten stderr line.
class Progress {
 public:
  Progress(int repetitions) : repetitions_(repetitions), start_(std::chrono::steady_clock::now()) {}
  void operator()(int done, int total) const {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = done > 0 ? elapsed * (total - done) / done : 0.0;
    const int cells = total / repetitions_;
    const int cell = std::min(cells, (done + repetitions_ - 1) / repetitions_);
    std::fprintf(stderr, "\rgrid: cell %d of %d, run %d of %d, %.0f s elapsed, about %.0f s left   ", cell, cells,
                 done, total, elapsed, left);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

 private:
  int repetitions_;
  std::chrono::steady_clock::time_point start_;
};

std::filesystem::path csv_beside(const std::filesystem::path& json) {
  std::filesystem::path csv = json;
  csv.replace_extension(".csv");
  return csv;
}

int run_grid_command(const GridCommandOptions& o) {
  Result<Case> c = find_case(o.case_name);
  if (!c) return fail_input(c.error().message);

  GridOptions options;
  options.fracturer = o.fracturer;
  options.stress_model = o.stress;
  if (o.budget_ms) {
    if (!(*o.budget_ms > 0.0) || !std::isfinite(*o.budget_ms))
      return fail_input(fmt::format("--budget-ms: must be a finite number > 0, got {}", *o.budget_ms));
    options.budget_ms = *o.budget_ms;
  }
  if (o.frames && *o.frames < 1) return fail_input(fmt::format("--frames: must be >= 1, got {}", *o.frames));
  options.frames = o.frames.value_or(0);
  options.repetitions = o.repetitions;
  options.prefracture = o.prefracture;
  options.runtime = o.runtime;
  options.no_skip = o.no_skip;
  if (Status s = check_grid_options(*c, options); !s) return fail_input(s.error().message);

  std::filesystem::path json_path, csv_path;
  if (!o.json.empty()) {
    json_path = o.json;
    if (std::filesystem::is_directory(json_path)) return fail_input("--json: " + o.json + " is a folder, not a file");
    if (json_path.extension() == ".csv") return fail_input("--json: " + o.json + " must not end in .csv (the CSV is written beside it)");
    csv_path = csv_beside(json_path);
    std::error_code ec;
    const std::filesystem::path parent = json_path.parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) return fail_input("--json: cannot create folder " + parent.string() + ": " + ec.message());
  }

  std::unique_ptr<PrefractureCache> cache;
  if (!o.no_cache) {
    const std::filesystem::path folder = o.cache_dir.empty() ? PrefractureCache::default_folder() : std::filesystem::path(o.cache_dir);
    if (!folder.empty()) cache = std::make_unique<PrefractureCache>(folder);
  }
  options.cache = cache.get();
  Progress progress(options.repetitions);
  if (isatty(STDERR_FILENO)) options.progress = [&progress](int done, int total) { progress(done, total); };

  Result<PreparedCase> prepared = prepare_case(std::move(*c));
  if (!prepared) return fail_input(prepared.error().message);
  Result<GridResult> grid = run_grid(*prepared, options);
  if (!grid) return fail_input(grid.error().message);

  std::cout << grid_to_markdown(*grid, prepared->spec.name) << std::flush;
  if (!json_path.empty()) {
    const std::string json = grid_to_json(*grid, prepared->spec, current_context()).dump(1) + "\n";
    if (Status s = write_file_atomically(json_path, json); !s) return fail_input("--json: " + s.error().message);
    if (Status s = write_file_atomically(csv_path, grid_to_csv(*grid)); !s) {
      return fail_input("--json: " + s.error().message);
    }
  }
  if (grid->passed()) return exit_ok;
  for (const GridCell& cell : grid->cells)
    if (!cell.within_budget)
      std::fprintf(stderr, "shatterbench: gate failed: cell %d x %d: worst frame %.3f ms > budget %g ms\n",
                   cell.prefracture, cell.runtime, cell.worst_frame_ms, grid->budget_ms);
  return exit_gate_failed;
}

}  // namespace

void add_grid_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<GridCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "grid", "Run a case over the pre-fracture x runtime grid, time every frame and stage, gate on the budget");
  cmd->add_option("--case", o->case_name, "Case file or built-in case name (see `shatterbench list`)")->required();
  cmd->add_option("--fracturer", o->fracturer, "Pre-fracture and runtime fracturer (default: the case's)");
  cmd->add_option("--stress", o->stress, "Stress model (default: the case's stress.model)");
  cmd->add_option("--budget-ms", o->budget_ms, "Frame budget in ms (default: the case's budget_ms, 33.3)");
  cmd->add_option("--repetitions", o->repetitions, "Runs per cell, each with its own seed (default 3)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--frames", o->frames, "Frames per run (default: the case's frames)");
  cmd->add_option("--json", o->json, "Write the results JSON here (and the CSV beside it, .csv)");
  cmd->add_option("--prefracture", o->prefracture, "Pre-fracture counts, e.g. 10,50,100 (default: the case's grid)")
      ->delimiter(',');
  cmd->add_option("--runtime", o->runtime, "Runtime counts, e.g. 5,25 (default: the case's grid)")->delimiter(',');
  cmd->add_flag("--no-skip", o->no_skip, "Turn every automatic stage skip off (cache, box culling, partial re-solves)");
  cmd->add_option("--cache-dir", o->cache_dir, "Pre-fracture cache folder (default: $SHATTERBENCH_CACHE, "
                                               "$XDG_CACHE_HOME/shatterbench or ~/.cache/shatterbench)");
  cmd->add_flag("--no-cache", o->no_cache, "Do not read or write the pre-fracture cache");
  cmd->callback([o, &exit_code] { exit_code = run_grid_command(*o); });
}

}  // namespace shatter::cli
