#include "harness/grid/grid_runner.h"

#include "harness/results/cell_checks.h"

#include "algorithms/core/self_intersection_verdicts.h"
#include "algorithms/fracture/fracture_limits.h"
#include "harness/grid/calibration.h"
#include "harness/grid/isolated_cell.h"
#include "harness/limits.h"
#include "harness/pipeline/frame/frame_recorder.h"
#include "harness/pipeline/instruction_marks.h"
#include "harness/pipeline/workers.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>

namespace shatter {
namespace {

Status check_counts(const std::vector<int>& counts, const std::string& what) {
  if (counts.empty()) return Error{what + ": at least one count is needed"};
  for (const int n : counts) {
    if (n < 1) return Error{what + ": counts must be >= 1, got " + std::to_string(n)};
    if (n > kMaxFragments)
      return Error{what + ": counts must be <= " + std::to_string(kMaxFragments) + " (the fragment limit), got " +
                   std::to_string(n)};
  }
  return {};
}

/// The case's settings under the grid's options (one fracturer for pre-fracture and runtime).
RunSettings grid_settings(const Case& c, const GridOptions& o) {
  CaseOverrides over;
  over.prefracture_fracturer = over.runtime_fracturer = o.fracturer;
  over.stress_model = o.stress_model;
  over.frames = o.frames;
  over.budget_ms = o.budget_ms;
  over.schedule = o.schedule;
  over.prefracture_counts = o.prefracture;
  over.runtime_counts = o.runtime;
  return resolve_settings(c, over);
}

/// The limits of harness/limits.h on the grid as a whole, once every value is known to be in range.
Status check_grid_limits(const Case& c, const GridOptions& o) {
  const RunSettings settings = grid_settings(c, o);
  const std::vector<int>& prefracture = settings.prefracture_counts;
  const std::vector<int>& runtime = settings.runtime_counts;
  const std::string axes = std::string(o.prefracture.empty() ? "grid.prefracture" : "--prefracture") + " x " +
                           (o.runtime.empty() ? "grid.runtime" : "--runtime");
  const auto cells = static_cast<std::int64_t>(prefracture.size()) * static_cast<std::int64_t>(runtime.size());
  if (cells > kMaxGridCells)
    return Error{fmt::format("{}: {} x {} = {} cells exceed the limit of {} cells per grid", axes, prefracture.size(),
                             runtime.size(), cells, kMaxGridCells)};
  const std::int64_t p = *std::max_element(prefracture.begin(), prefracture.end());
  const std::int64_t r = *std::max_element(runtime.begin(), runtime.end());
  if (p * r > kMaxRunPieces)
    return Error{
        fmt::format("{}: cell {} x {} can make {} runtime pieces, which exceeds the limit of {} pieces per run", axes,
                    p, r, p * r, kMaxRunPieces)};
  std::int64_t cells_here = 0;
  for (std::int64_t i = 0; i < cells; ++i) cells_here += i % o.shard_count == o.shard_index ? 1 : 0;
  const std::int64_t frames = settings.frames;
  const std::int64_t recorded = cells_here * o.repetitions * frames;
  if (recorded > kMaxRecordedFrames)
    return Error{
        fmt::format("--frames x --repetitions x cells: {} x {} x {} = {} frames recorded exceed the limit of {} "
                    "per grid (fewer frames, repetitions or cells, or --shard, bring it under)",
                    frames, o.repetitions, cells_here, recorded, kMaxRecordedFrames)};
  return {};
}

}  // namespace

Status check_grid_options(const Case& c, const GridOptions& o, const Registries& reg) {
  if (!o.fracturer.empty()) {
    if (auto f = reg.fracturers.create(o.fracturer); !f) return Error{"--fracturer: " + f.error().message, f.error().cause};
  } else {
    if (!c.prefracture.explicit_planes())
      if (auto f = reg.fracturers.create(c.prefracture.fracturer, c.prefracture.settings); !f)
        return Error{c.name + ": prefracture.fracturer: " + f.error().message, f.error().cause};
    if (auto f = reg.fracturers.create(c.runtime.fracturer, c.runtime.settings); !f)
      return Error{c.name + ": runtime.fracturer: " + f.error().message, f.error().cause};
  }
  if (!o.stress_model.empty()) {
    if (auto m = reg.stress_models.create(o.stress_model, settings_for(o.stress_model, c.stress.model, c.stress.settings)); !m)
      return Error{"--stress: " + m.error().message, m.error().cause};
  } else if (auto m = reg.stress_models.create(c.stress.model, c.stress.settings); !m) {
    return Error{c.name + ": stress.model: " + m.error().message, m.error().cause};
  }
  if (!std::isfinite(o.budget_ms) || o.budget_ms < 0.0)
    return Error{"--budget-ms: must be a finite number > 0, got " + std::to_string(o.budget_ms)};
  if (!std::isfinite(o.latency_budget_ms) || !(o.latency_budget_ms > 0.0))
    return Error{"--latency-budget-ms: must be a finite number > 0, got " + std::to_string(o.latency_budget_ms)};
  if (o.repetitions < 1) return Error{"--repetitions: must be >= 1, got " + std::to_string(o.repetitions)};
  if (o.repetitions > kMaxRepetitions)
    return Error{
        fmt::format("--repetitions: must be <= {} (the limit per cell), got {}", kMaxRepetitions, o.repetitions)};
  if (o.frames < 0) return Error{"--frames: must be >= 1, got " + std::to_string(o.frames)};
  if (o.frames > kMaxFrames)
    return Error{fmt::format("--frames: must be <= {} (the limit per run), got {}", kMaxFrames, o.frames)};
  if (!std::isfinite(o.cell_timeout_s) || o.cell_timeout_s < 0.0)
    return Error{fmt::format("--timeout: must be a finite number of seconds > 0, got {}", o.cell_timeout_s)};
  if (o.record_frames && o.cell_timeout_s > 0.0)
    return Error{"--record-frames: not available with --timeout (a recording does not cross back from the "
                 "forked child that runs a cell)"};
  if (o.threads < 1 || o.threads > kMaxWorkerThreads)
    return Error{fmt::format("--threads: must be in 1..{}, got {}", kMaxWorkerThreads, o.threads)};
  if (o.partition_samples < 0) return Error{"partition samples must be >= 0"};
  if (o.shard_count < 1 || o.shard_index < 0 || o.shard_index >= o.shard_count)
    return Error{"--shard: K/N needs N >= 1 and 0 <= K < N, got " + std::to_string(o.shard_index) + "/" +
                 std::to_string(o.shard_count)};
  if (!o.prefracture.empty())
    if (Status s = check_counts(o.prefracture, "--prefracture"); !s) return s;
  if (!o.runtime.empty())
    if (Status s = check_counts(o.runtime, "--runtime"); !s) return s;
  return check_grid_limits(c, o);
}

GridCell grid_cell_settings(const Case& c, const GridOptions& o, int p, int r) {
  GridCell cell;
  cell.prefracture = p;
  cell.runtime = r;
  const RunSettings settings = grid_settings(c, o);
  cell.prefracturer = settings.prefracturer;
  cell.fracturer = settings.runtime_fracturer;
  cell.stress = settings.stress_model;
  cell.schedule = std::string(schedule_mode_name(settings.schedule));
  return cell;
}

Result<GridCell> run_grid_cell(const PreparedCase& prepared, const GridOptions& o, const Registries& registries, int p,
                               int r, SelfIntersectionVerdicts* verdicts, int& done, int total,
                               std::int64_t poses_left) {
  const Case& c = prepared.spec;
  GridCell cell = grid_cell_settings(c, o, p, r);
  const RunSettings settings = grid_settings(c, o);
  SolverReport solves;  // of every repetition: a cell whose solve did not converge has no valid figures
  for (int rep = 0; rep < o.repetitions; ++rep) {
    RunOptions run;
    run.prefracture_fragments = p;
    run.runtime_fragments = r;
    if (!o.fracturer.empty()) {
      run.prefracture_fracturer = o.fracturer;
      run.runtime_fracturer = o.fracturer;
    }
    run.stress_model = o.stress_model;
    run.repetition = o.same_seed ? 0 : static_cast<std::uint64_t>(rep);
    run.frames = settings.frames;
    run.no_skip = o.no_skip;
    run.threads = o.threads;
    run.cache = o.cache;
    run.verdicts = verdicts;
    run.partition_samples = o.partition_samples;
    run.schedule = settings.schedule;
    std::optional<FrameRecorder> recorder;
    if (o.record_frames && rep == 0) {
      recorder.emplace(settings.frames, poses_left);
      run.recorder = &*recorder;
    }
    instruction_marks::set_run(p, r, rep);
    const double calibration_before = o.count_instructions ? 0.0 : calibration_ms();
    Result<RunResult> result = run_destruction(prepared, run, registries);
    // A recording past its limit is the user's request that cannot be met: the grid stops.
    if (!result && recorder && recorder->over_limit())
      return Error{fmt::format("--record-frames: cell {} x {}: {} (harness/limits.h; fewer frames or smaller cells)",
                               p, r, result.error().message)};
    // Every input was checked before the grid began (check_grid_options): what fails now is an
    // algorithm (a fracturer's or stress model's error, or its result refused by the output checks),
    // and it fails this cell alone, as a throw does; the grid goes on and writes every output.
    if (!result) return failed_grid_cell(cell, result.error().message);
    if (recorder) {
      cell.recording = recorder->finish(*result);
      cell.recording->prefracture = p;
      cell.recording->runtime = r;
      cell.recording->repetition = rep;
      cell.recording->seed = result->prefracture_seed;
    }
    cell.samples.push_back(run_sample(*result, o.extra_figures));
    if (!o.count_instructions) cell.samples.back().calibration_ms = 0.5 * (calibration_before + calibration_ms());
    add_run_accuracy(cell.accuracy, *result, rep == 0);
    add_solver_report(solves, result->solver);
    add_cell_stages(cell, result->stages.run(), result->stages.skips());
    if (o.progress) o.progress(++done, total);
  }
  summarise_cell(cell, settings.budget_ms, o.latency_budget_ms);
  if (!solves.converged) {
    cell.failed = convergence_failure(solves);
    cell.within_budget = cell.within_latency_budget = false;
  }
  return cell;
}

Result<GridResult> run_grid(const PreparedCase& prepared, const GridOptions& o, const Registries& registries) {
  const Case& c = prepared.spec;
  if (Status s = check_grid_options(c, o, registries); !s) return s.error();
  const auto start = std::chrono::steady_clock::now();
  const RunSettings settings = grid_settings(c, o);
  const std::vector<int>& prefracture = settings.prefracture_counts;
  const std::vector<int>& runtime = settings.runtime_counts;

  GridResult out;
  out.budget_ms = settings.budget_ms;
  out.latency_budget_ms = o.latency_budget_ms;
  out.repetitions = o.repetitions;
  out.frames = settings.frames;
  out.no_skip = o.no_skip;
  out.threads = o.threads;
  out.same_seed = o.same_seed;
  out.shard_index = o.shard_index;
  out.shard_count = o.shard_count;
  out.cell_timeout_s = o.cell_timeout_s;
  int cells_here = 0;
  for (std::size_t i = 0; i < prefracture.size() * runtime.size(); ++i)
    cells_here += static_cast<int>(i % static_cast<std::size_t>(o.shard_count)) == o.shard_index ? 1 : 0;
  const int total = cells_here * o.repetitions;
  int done = 0;
  // The cells of a row break the same pre-fracture: its fragments are checked once for the whole grid.
  SelfIntersectionVerdicts verdicts;
  std::int64_t poses_left = kMaxRecordedPoses;  // over every recorded cell
  std::size_t cell_index = 0;
  for (const int p : prefracture) {
    for (const int r : runtime) {
      if (static_cast<int>(cell_index++ % static_cast<std::size_t>(o.shard_count)) != o.shard_index) continue;
      Result<GridCell> cell = Error{""};
      const auto cell_start = std::chrono::steady_clock::now();
      if (o.cell_timeout_s > 0.0) {
        // The child runs and times the cell; its progress calls count on from `done` in its own copy.
        const int before = done;
        cell = run_cell_isolated([&] { return run_grid_cell(prepared, o, registries, p, r, &verdicts, done, total); },
                                 grid_cell_settings(c, o, p, r), o.cell_timeout_s, o.latency_budget_ms);
        done = before + o.repetitions;
        if (o.progress) o.progress(done, total);
      } else {
        // An exception out of a plugin's code fails its cell, as in a child; a crash needs --timeout.
        const int before = done;
        try {
          cell = run_grid_cell(prepared, o, registries, p, r, &verdicts, done, total, poses_left);
        } catch (const std::exception& e) {
          cell = failed_grid_cell(grid_cell_settings(c, o, p, r), std::string("threw: ") + e.what());
          done = before + o.repetitions;
          if (o.progress) o.progress(done, total);
        } catch (...) {
          cell = failed_grid_cell(grid_cell_settings(c, o, p, r), "threw a non-standard exception");
          done = before + o.repetitions;
          if (o.progress) o.progress(done, total);
        }
      }
      if (!cell) return cell.error();
      if (cell->recording)
        poses_left -= static_cast<std::int64_t>(cell->recording->bodies.size()) * cell->recording->frames;
      cell->wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - cell_start).count();
      out.cells.push_back(std::move(*cell));
    }
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace shatter
