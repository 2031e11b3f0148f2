#include "harness/cases/case_library.h"
#include "harness/cases/case_mesh.h"
#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/results/cell_checks.h"
#include "harness/grid/grid_runner.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_targets.h"
#include "harness/process/child_process.h"
#include "harness/results/callgrind_dumps.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_reader.h"
#include "harness/results/grid_reporter.h"
#include "harness/results/input_solid_json.h"
#include "harness/results/recorded_frames.h"
#include "harness/results/run_context.h"
#include "harness/pipeline/instruction_marks.h"

#include <fmt/core.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
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
  int repetitions = 5;
  std::optional<int> frames;
  std::string json;
  RecordFlags record;  // --record, --db
  std::vector<int> prefracture;
  std::vector<int> runtime;
  bool no_skip = false;
  bool same_seed = false;
  int threads = 1;
  std::string cache_dir;
  bool no_cache = false;
  std::string format = "shatter";
  std::string gbench;
  bool gbench_aggregates_only = false;
  std::string junit;
  std::string shard;
  std::string metric = "time";
  bool update_baseline = false;
  std::string baseline_dir = "results/baselines";
  std::string schedule;
  double latency_budget_ms = 50.0;
  std::optional<double> timeout_s;
  bool no_repair = false;
  double cap_uv_scale = 0.0;  // 0: the case's
  bool record_frames = false;
};

/// "K/N" -> (K, N); false when malformed.
bool parse_shard(const std::string& text, int& index, int& count) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return false;
  try {
    std::size_t a = 0, b = 0;
    index = std::stoi(text.substr(0, slash), &a);
    count = std::stoi(text.substr(slash + 1), &b);
    return a == slash && b == text.size() - slash - 1;
  } catch (const std::exception&) {
    return false;
  }
}

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

/// Runs this same grid under callgrind with stage marks on and returns the child's results with the
/// instruction counts attached (docs/compare.md, instruction mode). The child gets an argument
/// vector, never a shell line: paths and names pass through as data.
Result<GridResult> run_under_callgrind(const GridCommandOptions& o, const std::filesystem::path& exe) {
  if (!program_runs("valgrind", "--version"))
    return Error{"--metric instructions: valgrind is not installed (scripts/install-deps installs it)"};
  std::error_code ec;
  const auto folder = temporary_beside(std::filesystem::temp_directory_path() / "shatterbench-callgrind");
  if (!std::filesystem::create_directories(folder, ec))
    return Error{"--metric instructions: cannot create " + folder.string() + ": " + ec.message()};
  const auto child_json = folder / "child.json";
  std::vector<std::string> argv = {"valgrind", "--tool=callgrind", "--callgrind-out-file=" + (folder / "cg.out").string(),
                                   "--dump-instr=no", "--dump-line=no", exe.string(), "grid", "--case", o.case_name,
                                   "--metric", "instructions", "--repetitions", std::to_string(o.repetitions),
                                   "--json", child_json.string()};
  const auto add = [&argv](std::string flag, std::string value) {
    argv.push_back(std::move(flag));
    argv.push_back(std::move(value));
  };
  if (!o.fracturer.empty()) add("--fracturer", o.fracturer);
  if (!o.stress.empty()) add("--stress", o.stress);
  if (o.budget_ms) add("--budget-ms", fmt::format("{}", *o.budget_ms));
  if (o.frames) add("--frames", std::to_string(*o.frames));
  const auto list = [](const std::vector<int>& v) {
    std::string t;
    for (std::size_t i = 0; i < v.size(); ++i) t += (i ? "," : "") + std::to_string(v[i]);
    return t;
  };
  if (!o.prefracture.empty()) add("--prefracture", list(o.prefracture));
  if (!o.runtime.empty()) add("--runtime", list(o.runtime));
  if (o.no_skip) argv.push_back("--no-skip");
  if (o.same_seed) argv.push_back("--same-seed");
  if (o.threads != 1) add("--threads", std::to_string(o.threads));
  if (o.no_cache) argv.push_back("--no-cache");
  if (o.no_repair) argv.push_back("--no-repair");
  if (o.cap_uv_scale > 0.0) add("--cap-uv-scale", fmt::format("{}", o.cap_uv_scale));
  if (!o.cache_dir.empty()) add("--cache-dir", o.cache_dir);
  if (!o.shard.empty()) add("--shard", o.shard);
  if (!o.schedule.empty()) add("--schedule", o.schedule);
  add("--latency-budget-ms", fmt::format("{}", o.latency_budget_ms));
  ChildOptions child;
  child.stdout_file = "/dev/null";
  child.stderr_file = folder / "child.log";
  const Result<ChildExit> ran = run_child(argv, child);
  const auto cleanup = [&] { std::filesystem::remove_all(folder, ec); };
  if (!ran || !ran->exited || ran->code > 1) {
    std::string log = ran ? "" : ran.error().message;
    std::ifstream in(folder / "child.log");
    for (std::string line; std::getline(in, line);) log = line;  // the last line says why
    cleanup();
    return Error{"--metric instructions: the run under callgrind failed: " + log};
  }
  Result<StoredGrid> stored = read_grid_results(child_json);
  if (!stored) {
    cleanup();
    return stored.error();
  }
  Result<std::vector<InstructionDump>> dumps = read_instruction_dumps(folder, "cg.out");
  if (!dumps) {
    cleanup();
    return dumps.error();
  }
  GridResult grid = std::move(stored->grid);
  Status attached = attach_instructions(grid, *dumps);
  cleanup();
  if (!attached) return attached.error();
  return grid;
}

int run_grid_command(const GridCommandOptions& o, const Registries& registries) {
  Result<Case> c = find_case(o.case_name);
  if (!c) return fail_input(c.error().message);
  if (o.no_repair) refuse_repair(*c);
  if (o.cap_uv_scale > 0.0) set_cap_uv_scale(*c, o.cap_uv_scale);

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
  options.same_seed = o.same_seed;
  options.threads = o.threads;
  options.count_instructions = o.metric == "instructions" && instruction_marks::running_on_valgrind();
  if (!o.schedule.empty()) {
    options.schedule = schedule_mode_from_name(o.schedule);
    if (!options.schedule)
      return fail_input("--schedule: unknown mode \"" + o.schedule + "\" (allowed: immediate, prefetch, amortized)");
  }
  if (!(o.latency_budget_ms > 0.0) || !std::isfinite(o.latency_budget_ms))
    return fail_input(fmt::format("--latency-budget-ms: must be a finite number > 0, got {}", o.latency_budget_ms));
  options.latency_budget_ms = o.latency_budget_ms;
  if (!o.shard.empty() && !parse_shard(o.shard, options.shard_index, options.shard_count))
    return fail_input("--shard: expected K/N (e.g. 0/4), got \"" + o.shard + "\"");
  if (o.format != "shatter" && o.format != "gbench")
    return fail_input("--format: must be shatter or gbench, got \"" + o.format + "\"");
  if (o.metric != "time" && o.metric != "instructions")
    return fail_input("--metric: must be time or instructions, got \"" + o.metric + "\"");
  if (o.timeout_s) {
    if (!(*o.timeout_s > 0.0) || !std::isfinite(*o.timeout_s))
      return fail_input(fmt::format("--timeout: must be a finite number of seconds > 0, got {}", *o.timeout_s));
    // Under callgrind a cell runs some 50 times slower and the grid is one valgrind process: a wall-time
    // limit per cell would measure valgrind, and a forked child's counts would not reach the dump.
    if (o.metric == "instructions")
      return fail_input(
          "--timeout: not available with --metric instructions (cells counted under callgrind run in "
          "one process, without a time limit)");
    options.cell_timeout_s = *o.timeout_s;
  }
  options.record_frames = o.record_frames;
  if (o.record_frames) {
    if (o.update_baseline) return fail_input("--record-frames: not with --update-baseline (a baseline holds no recording)");
    if (o.json.empty())
      return fail_input("--record-frames: needs --json OUT (the recording is written beside it, OUT.frames.bin)");
    if (o.metric == "instructions")
      return fail_input("--record-frames: not with --metric instructions (record a run that is timed, not counted)");
  }
  if (Status s = check_grid_options(*c, options, registries); !s) return fail_algorithm("", s.error());
  if (Status s = check_record_target(o.record); !s) return fail_input(s.error().message);

  std::filesystem::path json_path = o.json;
  if (o.update_baseline) {
    if (o.format != "shatter") return fail_input("--update-baseline: baselines are written in the shatter format");
    if (!o.shard.empty()) return fail_input("--update-baseline: a baseline is a whole grid, not a shard");
    if (json_path.empty()) {
      json_path = std::filesystem::path(o.baseline_dir) / (c->name + ".json");
      // The first baseline of a project makes its folder; no other output creates folders.
      std::error_code ec;
      std::filesystem::create_directories(o.baseline_dir, ec);
      if (ec) return fail_input("--baseline-dir: cannot create " + o.baseline_dir + ": " + ec.message());
    }
  }
  std::filesystem::path csv_path;
  std::filesystem::path frames_path;
  if (!json_path.empty()) {
    if (json_path.extension() == ".csv")
      return fail_input("--json: " + json_path.string() + " must not end in .csv (the CSV is written beside it)");
    csv_path = csv_beside(json_path);
    if (o.record_frames) frames_path = recorded_frames_beside(json_path);
  }
  const std::vector<OutputTarget> outputs = {{"--json", json_path, false, o.update_baseline},
                                             {"--json (its CSV twin)", csv_path, false, o.update_baseline},
                                             {"--record-frames (beside --json)", frames_path, false, false},
                                             {"--gbench", o.gbench, false, false},
                                             {"--junit", o.junit, false, false}};
  // A case named by a file is an input no output may replace (a built-in name is no file here).
  std::vector<std::filesystem::path> inputs;
  if (std::error_code ec; std::filesystem::is_regular_file(o.case_name, ec)) inputs.emplace_back(o.case_name);
  if (Status s = check_outputs(outputs, baseline_folders(o.baseline_dir), inputs); !s) return fail_input(s.error().message);

  std::unique_ptr<PrefractureCache> cache;
  if (!o.no_cache) {
    const std::filesystem::path folder =
        o.cache_dir.empty() ? PrefractureCache::default_folder() : std::filesystem::path(o.cache_dir);
    if (Status s = check_outside_baselines("--cache-dir", folder, baseline_folders(o.baseline_dir)); !s)
      return fail_input(s.error().message);
    if (!folder.empty()) cache = std::make_unique<PrefractureCache>(folder);
  }
  options.cache = cache.get();
  Progress progress(options.repetitions);
  if (isatty(STDERR_FILENO)) options.progress = [&progress](int done, int total) { progress(done, total); };

  const bool instructions = o.metric == "instructions";
  const bool marking = instructions && instruction_marks::running_on_valgrind();
  if (marking) instruction_marks::enable(true);

  Result<PreparedCase> prepared = prepare_case(std::move(*c));
  if (!prepared) return fail_input(prepared.error().message);
  Result<GridResult> grid = Error{""};
  if (instructions && !marking) {
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return fail_input("--metric instructions: cannot find the running executable: " + ec.message());
    grid = run_under_callgrind(o, exe);
  } else {
    grid = run_grid(*prepared, options, registries);
  }
  if (!grid) return fail_input(grid.error().message);

  GridReport report{*grid, prepared->spec.name, case_to_json(prepared->spec), RunContext{},
                    input_solid_json(prepared->solid)};
  std::cout << make_grid_reporter(instructions && !marking ? "instructions-markdown" : "markdown")->render(report)
            << std::flush;
  // Instruction mode times are valgrind's, not the game's: the budget gate applies to time mode only.
  // The result checks of the fractures (cell_checks.h) apply in both modes.
  const bool checks_failed = std::any_of(grid->cells.begin(), grid->cells.end(),
                                         [](const GridCell& cell) { return !failed_cell_checks(cell).empty(); });
  const bool gate_failed = (!instructions && !grid->passed()) || checks_failed;
  if (o.update_baseline && gate_failed)
    std::fprintf(stderr, "shatterbench: baseline %s not updated: the budget gate failed\n", json_path.string().c_str());
  // One context for every output of the run: the recorded run is the --json file's run, byte for byte.
  report.context = current_context();
  if (!json_path.empty() && !(o.update_baseline && gate_failed)) {
    std::string frames;
    if (o.record_frames) {
      // Lent to the encoder and given back: the JSON's block describes them.
      std::vector<RecordedFrames> recordings;
      for (GridCell& cell : grid->cells)
        if (cell.recording) recordings.push_back(std::move(*cell.recording));
      frames = encode_recorded_frames(recordings);
      std::size_t k = 0;
      for (GridCell& cell : grid->cells)
        if (cell.recording) *cell.recording = std::move(recordings[k++]);
      grid->recorded_frames_file = frames_path.filename().string();
      grid->recorded_frames_bytes = frames.size();
    }
    const std::string json = make_grid_reporter(o.format == "gbench" ? "gbench" : "json")->render(report);
    const std::string csv = make_grid_reporter("csv")->render(report);
    std::vector<FileContent> set = {{json_path, json}, {csv_path, csv}};
    if (o.record_frames) set.push_back({frames_path, frames});
    if (Status s = write_files_atomically(set); !s) return fail_input("--json: " + s.error().message);
    if (o.update_baseline) std::fprintf(stderr, "shatterbench: baseline %s updated\n", json_path.string().c_str());
  }
  if (!o.gbench.empty()) {
    const std::string format = o.gbench_aggregates_only ? "gbench-aggregates" : "gbench";
    if (Status s = write_file_atomically(o.gbench, make_grid_reporter(format)->render(report)); !s)
      return fail_input("--gbench: " + s.error().message);
  }
  if (!o.junit.empty())
    if (Status s = write_file_atomically(o.junit, make_grid_reporter("junit")->render(report)); !s)
      return fail_input("--junit: " + s.error().message);
  // The run is recorded whatever its verdict: a broken budget is part of the history.
  if (o.record.record) {
    const std::string json = make_grid_reporter("json")->render(report);
    if (const int code = record_if_asked(o.record, json, json_path.empty() ? prepared->spec.name + ".json" : json_path.string());
        code != exit_ok)
      return code;
  }
  if (!gate_failed) return exit_ok;
  for (const GridCell& cell : grid->cells)
    print_failed_checks(fmt::format("cell {} x {}", cell.prefracture, cell.runtime), failed_cell_checks(cell));
  for (const GridCell& cell : grid->cells)
    if (!cell.failed.empty())
      std::fprintf(stderr, "shatterbench: gate failed: cell %d x %d: %s\n", cell.prefracture, cell.runtime,
                   cell.failed.c_str());
  for (const GridCell& cell : grid->cells)
    if (cell.failed.empty() && !cell.within_budget)
      std::fprintf(stderr, "shatterbench: gate failed: cell %d x %d: worst frame %.3f ms > budget %g ms\n",
                   cell.prefracture, cell.runtime, cell.worst_frame_ms, grid->budget_ms);
  for (const GridCell& cell : grid->cells)
    if (cell.failed.empty() && !cell.within_latency_budget)
      std::fprintf(stderr,
                   "shatterbench: gate failed: cell %d x %d: latency %.3f ms (%g frames, schedule %s) > latency "
                   "budget %g ms\n",
                   cell.prefracture, cell.runtime, cell.summaries.value_or("latency_ms", 0.0),
                   cell.summaries.value_or("latency_frames", 0.0), cell.schedule.c_str(),
                   grid->latency_budget_ms);
  return exit_gate_failed;
}

}  // namespace

void add_grid_command(CLI::App& app, int& exit_code, const Registries& registries) {
  auto o = std::make_shared<GridCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "grid", "Run a case over the pre-fracture x runtime grid, time every frame and stage, gate on the budget");
  cmd->add_option("--case", o->case_name, "Case file or built-in case name (see `shatterbench list`)")->required();
  cmd->add_option("--fracturer", o->fracturer, "Pre-fracture and runtime fracturer (default: the case's)");
  cmd->add_option("--stress", o->stress, "Stress model (default: the case's stress.model)");
  cmd->add_option("--budget-ms", o->budget_ms, "Frame budget in ms (default: the case's budget_ms, 33.3)");
  cmd->add_option("--repetitions", o->repetitions, "Runs per cell, each with its own seed (default 5: the fewest whose U test can show a change between two runs)")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));  // kMaxRepetitions: check_grid_limits
  cmd->add_option("--frames", o->frames, "Frames per run (default: the case's frames)");
  cmd->add_option("--json", o->json, "Write the results JSON here (and the CSV beside it, .csv)");
  add_record_flags(cmd, o->record);
  cmd->add_option("--format", o->format, "Format of the --json file: shatter (default) or gbench (Google Benchmark's)");
  cmd->add_option("--gbench", o->gbench,
                  "Also write Google Benchmark's JSON here (for its tools/compare.py; docs/results.md), beside --json");
  cmd->add_flag("--gbench-aggregates-only", o->gbench_aggregates_only,
                "In --gbench, only the mean, median, stddev and cv of the repetitions");
  cmd->add_option("--junit", o->junit, "Write JUnit XML here: one test case per cell (the budget gate)");
  cmd->add_option("--prefracture", o->prefracture, "Pre-fracture counts, e.g. 10,50,100 (default: the case's grid)")
      ->delimiter(',');
  cmd->add_option("--runtime", o->runtime, "Runtime counts, e.g. 5,25 (default: the case's grid)")->delimiter(',');
  cmd->add_option("--shard", o->shard, "Run every N-th cell starting at K (K/N, 0 <= K < N); join with `merge`");
  cmd->add_option("--metric", o->metric, "time (default) or instructions (counted under callgrind, per stage and frame)");
  cmd->add_flag("--same-seed", o->same_seed,
                "Every repetition repeats the case's seed (the same workload): for regression gates");
  cmd->add_option("--threads", o->threads,
                  "Threads of each run: the runtime event's fractures and colliders and each physics step's "
                  "pair tests run on this many at once (default 1, single-threaded as the seed measured)");
  cmd->add_flag("--record-frames", o->record_frames,
                "Record the first repetition of every cell for playback: every body's pose and contacts in "
                "every frame, the frame's stage times and the bodies' meshes, into OUT.frames.bin beside --json "
                "OUT (docs/results.md)");
  cmd->add_flag("--no-skip", o->no_skip, "Turn every automatic stage skip off (cache, box culling, partial re-solves)");
  cmd->add_option("--schedule", o->schedule,
                  "Schedule of the runtime event: immediate, prefetch or amortized (default: the case's schedule.mode)");
  cmd->add_option("--latency-budget-ms", o->latency_budget_ms,
                  "Gate on each cell's latency, trigger to visible at 60 Hz, in ms (default 50)");
  cmd->add_option("--timeout", o->timeout_s,
                  "Wall-time limit per cell in s: each cell runs in a forked child; a cell past it fails "
                  "(\"timeout after S s\") and the grid goes on (default: none, no fork)");
  cmd->add_option("--cache-dir", o->cache_dir, "Pre-fracture cache folder (default: $SHATTERBENCH_CACHE, "
                                               "$XDG_CACHE_HOME/shatterbench or ~/.cache/shatterbench)");
  cmd->add_flag("--no-cache", o->no_cache, "Do not read or write the pre-fracture cache");
  cmd->add_flag("--no-repair", o->no_repair, "Refuse a mesh file that is not a solid instead of repairing it");
  add_cap_uv_scale_option(cmd, o->cap_uv_scale);
  cmd->add_flag("--update-baseline", o->update_baseline,
                "Write the results as the case's baseline (BASELINE-DIR/<case>.json, or --json); the only way a baseline changes");
  cmd->add_option("--baseline-dir", o->baseline_dir, "Baseline folder (default results/baselines)");
  cmd->callback([o, &exit_code, &registries] { exit_code = run_grid_command(*o, registries); });
}

}  // namespace shatter::cli
