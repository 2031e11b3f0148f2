#include "harness/grid/grid_runner.h"

#include "harness/grid/cell_checks.h"

#include "algorithms/core/self_intersection_verdicts.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/registry/register_all.h"
#include "harness/grid/calibration.h"
#include "harness/grid/isolated_cell.h"
#include "harness/limits.h"
#include "harness/pipeline/instruction_marks.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

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

/// The pre-fracture counts a grid runs: the flag's, else the case's; explicit planes make one.
std::vector<int> prefracture_counts(const Case& c, const GridOptions& o) {
  if (c.prefracture.explicit_planes()) return {static_cast<int>(c.prefracture.planes.size()) + 1};
  return o.prefracture.empty() ? c.grid.prefracture : o.prefracture;
}

/// The runtime counts a grid runs: the flag's, else the case's.
const std::vector<int>& runtime_counts(const Case& c, const GridOptions& o) {
  return o.runtime.empty() ? c.grid.runtime : o.runtime;
}

/// The limits of harness/limits.h on the grid as a whole, once every value is known to be in range.
Status check_grid_limits(const Case& c, const GridOptions& o) {
  const std::vector<int> prefracture = prefracture_counts(c, o);
  const std::vector<int>& runtime = runtime_counts(c, o);
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
  const std::int64_t frames = o.frames > 0 ? o.frames : c.frames;
  const std::int64_t recorded = cells_here * o.repetitions * frames;
  if (recorded > kMaxRecordedFrames)
    return Error{
        fmt::format("--frames x --repetitions x cells: {} x {} x {} = {} frames recorded exceed the limit of {} "
                    "per grid (fewer frames, repetitions or cells, or --shard, bring it under)",
                    frames, o.repetitions, cells_here, recorded, kMaxRecordedFrames)};
  return {};
}

double median_over(const std::vector<GridSample>& samples, double GridSample::*field) {
  std::vector<double> v;
  for (const GridSample& s : samples) v.push_back(s.*field);
  return median_of(v);
}

StageTimes median_stages(const std::vector<GridSample>& samples, StageTimes GridSample::*field) {
  StageTimes out{};
  std::vector<double> v;
  for (std::size_t k = 0; k < kStageCount; ++k) {
    v.clear();
    for (const GridSample& s : samples) v.push_back((s.*field)[k]);
    out[k] = median_of(v);
  }
  return out;
}

std::string fmt_cell_error(int prefracture, int runtime, const std::string& message) {
  return "cell " + std::to_string(prefracture) + " x " + std::to_string(runtime) + ": " + message;
}

GridSample sample_of(const RunResult& run) {
  GridSample s;
  s.seed = run.prefracture_seed;
  s.frame_ms = run.frame_ms;
  s.event_ms = run.event_ms;
  s.event_frame = run.event_frames.empty() ? -1 : run.event_frames.front();
  s.worst_frame_ms = run.frame_ms.empty() ? 0.0 : *std::max_element(run.frame_ms.begin(), run.frame_ms.end());
  s.stages_ms = run.frame_stages.wall;
  s.setup_ms = run.setup.wall;
  s.stages_cpu_ms = run.frame_stages.cpu;
  s.worst_frame_cpu_ms =
      run.frame_cpu_ms.empty() ? 0.0 : *std::max_element(run.frame_cpu_ms.begin(), run.frame_cpu_ms.end());
  s.cache_hit = run.cache_hit;
  s.fragments = static_cast<int>(run.fragments.size());
  s.hit = static_cast<int>(run.hit.size());
  for (const auto& p : run.pieces) s.pieces += static_cast<int>(p.size());
  s.broken_bonds = static_cast<int>(std::count(run.broken.begin(), run.broken.end(), std::uint8_t{1}));
  s.falling_clusters = static_cast<int>(run.falling_clusters.size());
  s.bodies = run.bodies;
  s.solver = run.solver;
  s.latency_ms = run.latency.ms;
  s.latency_frames = run.latency.frames;
  s.latency_after_impact_frames = run.latency.after_impact;
  s.trigger_frame = run.latency.visible_frame >= 0 ? run.latency.trigger_frame : -1;
  s.visible_frame = run.latency.visible_frame;
  s.event_steps = static_cast<int>(run.step_ms.size());
  s.largest_step_ms = run.largest_step_ms;
  s.worst_work_ms = run.frame_work_ms.empty() ? 0.0 : *std::max_element(run.frame_work_ms.begin(), run.frame_work_ms.end());
  s.bodies_peak = run.bodies_peak;
  s.faded = run.faded;
  s.particles_spawned = run.particles_spawned;
  s.particles_peak = run.particles_peak;
  return s;
}

void add_error(CellError& e, const RunResult& run, bool first) {
  const FractureMetrics& p = run.prefracture_error;
  const RuntimeFractureError& r = run.runtime_error;
  e.prefracture_volume_error = std::max(e.prefracture_volume_error, p.volume_error);
  e.prefracture_partition_error = std::max(e.prefracture_partition_error, p.partition_error);
  e.prefracture_all_closed = e.prefracture_all_closed && p.all_closed;
  e.prefracture_min_fragment_volume =
      first ? p.min_fragment_volume : std::min(e.prefracture_min_fragment_volume, p.min_fragment_volume);
  e.runtime_volume_error = std::max(e.runtime_volume_error, r.volume_error);
  e.runtime_partition_error = std::max(e.runtime_partition_error, r.partition_error);
  e.runtime_all_closed = e.runtime_all_closed && r.all_closed;
  if (r.pieces > 0)
    e.runtime_min_fragment_volume = e.runtime_min_fragment_volume == 0.0
                                        ? r.min_fragment_volume
                                        : std::min(e.runtime_min_fragment_volume, r.min_fragment_volume);
  e.solver_converged = e.solver_converged && run.solver.converged;
  e.solver_residual = std::max(e.solver_residual, run.solver.residual);
}

void merge_stages(GridCell& cell, const RunResult& run) { add_cell_stages(cell, run.stages.run(), run.stages.skips()); }

}  // namespace

void summarise_schedule(GridCell& cell, double latency_budget_ms) {
  std::vector<double> latency, frames, bodies, peak, particles;
  cell.largest_step_ms = 0.0;
  for (const GridSample& s : cell.samples) {
    latency.push_back(s.latency_ms);
    frames.push_back(s.latency_frames);
    bodies.push_back(s.bodies);
    peak.push_back(s.bodies_peak);
    particles.push_back(s.particles_peak);
    cell.largest_step_ms = std::max(cell.largest_step_ms, s.largest_step_ms);
  }
  cell.latency_ms = median_of(latency);
  cell.latency_frames = median_of(frames);
  cell.bodies = median_of(bodies);
  cell.bodies_peak = median_of(peak);
  cell.particles_peak = median_of(particles);
  cell.within_latency_budget = cell.latency_ms <= latency_budget_ms;
}

void summarise_cell(GridCell& cell, double budget_ms, double latency_budget_ms) {
  std::vector<double> frames;
  for (const GridSample& s : cell.samples) frames.insert(frames.end(), s.frame_ms.begin(), s.frame_ms.end());
  cell.frame_ms = sample_statistics(frames);
  cell.worst_frame_ms = median_over(cell.samples, &GridSample::worst_frame_ms);
  cell.event_ms = median_over(cell.samples, &GridSample::event_ms);
  cell.stages_ms = median_stages(cell.samples, &GridSample::stages_ms);
  cell.setup_ms = median_stages(cell.samples, &GridSample::setup_ms);
  cell.within_budget = cell.worst_frame_ms <= budget_ms;
  summarise_schedule(cell, latency_budget_ms);
}

void add_cell_stages(GridCell& cell, const std::vector<std::string>& run, const std::vector<StageSkip>& skipped) {
  for (const std::string& name : run)
    if (std::find(cell.stages_run.begin(), cell.stages_run.end(), name) == cell.stages_run.end())
      cell.stages_run.push_back(name);
  // Keep data-flow order.
  std::vector<std::string> ordered;
  for (const Stage s : kAllStages) {
    const std::string name(stage_name(s));
    if (std::find(cell.stages_run.begin(), cell.stages_run.end(), name) != cell.stages_run.end())
      ordered.push_back(name);
  }
  cell.stages_run = std::move(ordered);
  for (const StageSkip& skip : skipped) {
    const bool known = std::any_of(cell.stages_skipped.begin(), cell.stages_skipped.end(), [&](const StageSkip& s) {
      return s.stage == skip.stage && s.reason == skip.reason;
    });
    if (!known) cell.stages_skipped.push_back(skip);
  }
}

void add_cell_error(CellError& into, const CellError& other) {
  into.prefracture_volume_error = std::max(into.prefracture_volume_error, other.prefracture_volume_error);
  into.prefracture_partition_error = std::max(into.prefracture_partition_error, other.prefracture_partition_error);
  into.prefracture_all_closed = into.prefracture_all_closed && other.prefracture_all_closed;
  into.prefracture_min_fragment_volume =
      std::min(into.prefracture_min_fragment_volume, other.prefracture_min_fragment_volume);
  into.runtime_volume_error = std::max(into.runtime_volume_error, other.runtime_volume_error);
  into.runtime_partition_error = std::max(into.runtime_partition_error, other.runtime_partition_error);
  into.runtime_all_closed = into.runtime_all_closed && other.runtime_all_closed;
  // 0 stands for "no runtime pieces" (add_error).
  if (into.runtime_min_fragment_volume == 0.0 || other.runtime_min_fragment_volume == 0.0)
    into.runtime_min_fragment_volume = std::max(into.runtime_min_fragment_volume, other.runtime_min_fragment_volume);
  else
    into.runtime_min_fragment_volume = std::min(into.runtime_min_fragment_volume, other.runtime_min_fragment_volume);
  into.solver_converged = into.solver_converged && other.solver_converged;
  into.solver_residual = std::max(into.solver_residual, other.solver_residual);
}

bool GridResult::passed() const {
  return std::all_of(cells.begin(), cells.end(),
                     [](const GridCell& c) {
                       return c.failed.empty() && c.within_budget && c.within_latency_budget && failed_cell_checks(c).empty();
                     });
}

Status check_grid_options(const Case& c, const GridOptions& o) {
  const auto& reg = registries();
  if (!o.fracturer.empty()) {
    if (auto f = reg.fracturers.create(o.fracturer); !f) return Error{"--fracturer: " + f.error().message};
  } else {
    if (!c.prefracture.explicit_planes())
      if (auto f = reg.fracturers.create(c.prefracture.fracturer); !f)
        return Error{c.name + ": prefracture.fracturer: " + f.error().message};
    if (auto f = reg.fracturers.create(c.runtime.fracturer); !f)
      return Error{c.name + ": runtime.fracturer: " + f.error().message};
  }
  if (!o.stress_model.empty()) {
    if (auto m = reg.stress_models.create(o.stress_model); !m) return Error{"--stress: " + m.error().message};
  } else if (auto m = reg.stress_models.create(c.stress.model); !m) {
    return Error{c.name + ": stress.model: " + m.error().message};
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
  cell.prefracturer = c.prefracture.explicit_planes() ? "planes"
                      : o.fracturer.empty()           ? c.prefracture.fracturer
                                                      : o.fracturer;
  cell.fracturer = o.fracturer.empty() ? c.runtime.fracturer : o.fracturer;
  cell.stress = o.stress_model.empty() ? c.stress.model : o.stress_model;
  cell.schedule = std::string(schedule_mode_name(o.schedule.value_or(c.schedule.mode)));
  return cell;
}

Result<GridCell> run_grid_cell(const PreparedCase& prepared, const GridOptions& o, int p, int r,
                               SelfIntersectionVerdicts* verdicts, int& done, int total) {
  const Case& c = prepared.spec;
  GridCell cell = grid_cell_settings(c, o, p, r);
  const double budget_ms = o.budget_ms > 0 ? o.budget_ms : c.budget_ms;
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
    run.frames = o.frames > 0 ? o.frames : c.frames;
    run.no_skip = o.no_skip;
    run.cache = o.cache;
    run.verdicts = verdicts;
    run.partition_samples = o.partition_samples;
    run.schedule = o.schedule.value_or(c.schedule.mode);
    instruction_marks::set_run(p, r, rep);
    const double calibration_before = o.count_instructions ? 0.0 : calibration_ms();
    Result<RunResult> result = run_destruction(prepared, run);
    if (!result) return Error{fmt_cell_error(p, r, result.error().message)};
    cell.samples.push_back(sample_of(*result));
    if (!o.count_instructions) cell.samples.back().calibration_ms = 0.5 * (calibration_before + calibration_ms());
    add_error(cell.error, *result, rep == 0);
    add_solver_report(solves, result->solver);
    merge_stages(cell, *result);
    if (o.progress) o.progress(++done, total);
  }
  summarise_cell(cell, budget_ms, o.latency_budget_ms);
  if (!solves.converged) {
    cell.failed = convergence_failure(solves);
    cell.within_budget = cell.within_latency_budget = false;
  }
  return cell;
}

Result<GridResult> run_grid(const PreparedCase& prepared, const GridOptions& o) {
  const Case& c = prepared.spec;
  if (Status s = check_grid_options(c, o); !s) return s.error();
  const auto start = std::chrono::steady_clock::now();
  // An explicit-plane pre-fracture has one fragment count: the grid's pre-fracture axis collapses to it.
  const std::vector<int> prefracture = prefracture_counts(c, o);
  const std::vector<int>& runtime = runtime_counts(c, o);

  GridResult out;
  out.budget_ms = o.budget_ms > 0 ? o.budget_ms : c.budget_ms;
  out.latency_budget_ms = o.latency_budget_ms;
  out.repetitions = o.repetitions;
  out.frames = o.frames > 0 ? o.frames : c.frames;
  out.no_skip = o.no_skip;
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
  std::size_t cell_index = 0;
  for (const int p : prefracture) {
    for (const int r : runtime) {
      if (static_cast<int>(cell_index++ % static_cast<std::size_t>(o.shard_count)) != o.shard_index) continue;
      Result<GridCell> cell = Error{""};
      if (o.cell_timeout_s > 0.0) {
        // The child runs and times the cell; its progress calls count on from `done` in its own copy.
        const int before = done;
        cell = run_cell_isolated([&] { return run_grid_cell(prepared, o, p, r, &verdicts, done, total); },
                                 grid_cell_settings(c, o, p, r), o.cell_timeout_s, o.latency_budget_ms);
        done = before + o.repetitions;
        if (o.progress) o.progress(done, total);
      } else {
        cell = run_grid_cell(prepared, o, p, r, &verdicts, done, total);
      }
      if (!cell) return cell.error();
      out.cells.push_back(std::move(*cell));
    }
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace shatter
