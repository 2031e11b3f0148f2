#pragma once
/// The grid runner (DESIGN.md section 8): every cell of pre-fracture count x runtime count, each run
/// `repetitions` times with a different seed, summarised per cell and gated on the frame budget.
///
/// Design note: the gate is on `worst_frame_ms`, the median over repetitions of each repetition's
/// slowest frame: the hitch a player sees, usually the event frame, robust to one noisy repetition
/// (a median of 3 needs two slow repetitions to move). The other figures are descriptive: `frame_ms`
/// pools every frame of every repetition; stage times are medians over repetitions of each
/// repetition's total per stage; accuracy figures are the worst over repetitions; every named figure
/// of a run's record is summarised as its spec says (results/run_figures.h: medians of the latency,
/// bodies and particles, the largest event step).

#include "algorithms/core/result.h"
#include "harness/cases/run_settings.h"
#include "harness/grid/run_sample.h"
#include "harness/limits.h"
#include "harness/pipeline/destruction_run.h"
#include "harness/results/cell_summary.h"
#include "harness/results/grid_record.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// What a grid run does; empty names and lists take the case's values (resolve_settings).
struct GridOptions {
  std::string fracturer;               ///< runtime and pre-fracture algorithm (empty: the case's)
  std::string stress_model;            ///< stress model (empty: the case's)
  double budget_ms = 0.0;              ///< frame budget, ms (0: the case's budget_ms)
  int repetitions = 5;                 ///< runs per cell, each with its own seed, >= 1 (5: the fewest whose U test can reach 0.01 between two runs)
  int frames = 0;                      ///< frames per run (0: the case's)
  std::vector<int> prefracture;        ///< pre-fracture counts (empty: the case's grid.prefracture)
  std::vector<int> runtime;            ///< runtime counts (empty: the case's grid.runtime)
  bool no_skip = false;                ///< every automatic skip off (see destruction_run.h)
  int threads = 1;                     ///< threads of each runtime event (RunOptions::threads), 1..kMaxWorkerThreads
  /// Every repetition repeats the case's seed (the same workload) instead of seed + k: what a
  /// regression gate wants, so that the repetitions differ by noise only (docs/compare.md).
  bool same_seed = false;
  const PrefractureCache* cache = nullptr;  ///< pre-fracture cache, or none
  int partition_samples = 256;         ///< points of the partition-error tests
  int shard_index = 0;                 ///< run the cells i with i % shard_count == shard_index
  int shard_count = 1;                 ///< number of shards (1: the whole grid)
  bool count_instructions = false;     ///< mark stage boundaries for the instruction counter (callgrind)
  std::optional<ScheduleMode> schedule;  ///< schedule mode of every run (none: the case's schedule.mode)
  double latency_budget_ms = 50.0;     ///< gate on each cell's latency_ms (trigger to visible), ms, > 0
  /// Wall-time limit per cell, s (0: none, every cell runs in this process). With a limit every cell
  /// runs in a forked child (isolated_cell.h): a cell past it, or one that crashes, becomes a failed
  /// cell and the grid goes on with the next one.
  double cell_timeout_s = 0.0;
  /// Record the first repetition of every cell for playback (frame/frame_recorder.h): each body's pose
  /// in every frame, at most kMaxRecordedPoses poses over the grid. Not with a cell timeout.
  bool record_frames = false;
  /// Called after each run with (runs done, runs in all); may be empty.
  std::function<void(int, int)> progress;
  /// Figures of the caller's own added to every run's record (run_sample.h); may be empty.
  ExtraFigures extra_figures;
};

/// Checks `options` against `c` before anything runs: algorithm names exist (errors name the flag or
/// the case key), counts >= 1, budget finite and > 0, repetitions and frames >= 1, the cell timeout
/// finite and >= 0, and the limits of harness/limits.h (repetitions, frames, fragment counts, cells,
/// pieces per run, frames recorded), and no recording (record_frames) with a cell timeout.
/// Plugins are looked up in `registries`.
Status check_grid_options(const Case& c, const GridOptions& options, const Registries& registries);

/// The cell `p` x `r` of a grid with `options`, its settings filled in and nothing run: what a cell
/// that failed reports.
GridCell grid_cell_settings(const Case& c, const GridOptions& options, int p, int r);

/// Runs one cell of the grid, every repetition in this process, passing `verdicts` (clean
/// self-intersection verdicts the grid shares between its cells, or none) to every run. `done` counts
/// the runs finished (for `options.progress`, out of `total`). With `options.record_frames` the first
/// repetition is recorded into the cell's `recording`, with at most `poses_left` poses: past them the
/// cell is an error ("--record-frames: cell P x R: ... exceed the limit ..."), not a failed cell.
Result<GridCell> run_grid_cell(const PreparedCase& prepared, const GridOptions& options, const Registries& registries,
                               int p, int r, SelfIntersectionVerdicts* verdicts, int& done, int total,
                               std::int64_t poses_left = kMaxRecordedPoses);

/// Runs the grid of `prepared` (options checked by check_grid_options).
Result<GridResult> run_grid(const PreparedCase& prepared, const GridOptions& options, const Registries& registries);

}  // namespace shatter
