#pragma once
/// The grid runner (DESIGN.md section 8): every cell of pre-fracture count x runtime count, each run
/// `repetitions` times with a different seed, summarised per cell and gated on the frame budget.
///
/// Design note: the gate is on `worst_frame_ms`, the median over repetitions of each repetition's
/// slowest frame: the hitch a player sees, usually the event frame, robust to one noisy repetition
/// (a median of 3 needs two slow repetitions to move). The other figures are descriptive: `frame_ms`
/// pools every frame of every repetition; stage times are medians over repetitions of each
/// repetition's total per stage; error figures are the worst over repetitions.

#include "algorithms/core/result.h"
#include "harness/pipeline/destruction_run.h"
#include "harness/results/sample_statistics.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// What a grid run does; empty names and lists take the case's values.
struct GridOptions {
  std::string fracturer;               ///< runtime and pre-fracture algorithm (empty: the case's)
  std::string stress_model;            ///< stress model (empty: the case's)
  double budget_ms = 0.0;              ///< frame budget, ms (0: the case's budget_ms)
  int repetitions = 3;                 ///< runs per cell, each with its own seed, >= 1
  int frames = 0;                      ///< frames per run (0: the case's)
  std::vector<int> prefracture;        ///< pre-fracture counts (empty: the case's grid.prefracture)
  std::vector<int> runtime;            ///< runtime counts (empty: the case's grid.runtime)
  bool no_skip = false;                ///< every automatic skip off (see destruction_run.h)
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
  /// Called after each run with (runs done, runs in all); may be empty.
  std::function<void(int, int)> progress;
};

/// Retired instructions of one run (instruction mode, docs/compare.md): per stage inside frames and in
/// the setup, per frame, and of the first event frame. Counts are held as doubles (exact below 2^53).
struct InstructionCounts {
  StageTimes stages{};                           ///< per stage, summed over the frames
  StageTimes setup{};                            ///< per stage, offline setup
  std::vector<double> frames;                    ///< per frame
  double event = 0.0;                            ///< the first event frame
  double worst_frame = 0.0;                      ///< the largest frame
};

/// One repetition of one cell, as kept in the results.
struct GridSample {
  std::uint64_t seed = 0;                        ///< seed of the pre-fracture and runtime fracture
  std::vector<double> frame_ms;                  ///< every frame
  double event_ms = 0.0;                         ///< the first event frame
  int event_frame = -1;                          ///< its index (-1: no impact landed)
  double worst_frame_ms = 0.0;                   ///< the slowest frame
  StageTimes stages_ms{};                        ///< stage times inside frames
  StageTimes setup_ms{};                         ///< offline stage times
  StageTimes stages_cpu_ms{};                    ///< thread CPU time of the stages inside frames
  double worst_frame_cpu_ms = 0.0;               ///< thread CPU time of the frame with the most of it
  double calibration_ms = 0.0;                   ///< the reference workload's CPU time around this run (calibration.h); 0 unknown
  bool cache_hit = false;                        ///< the pre-fracture came from the cache
  int fragments = 0;                             ///< pre-fracture fragments made
  int hit = 0;                                   ///< fragments the impact fractured
  int pieces = 0;                                ///< runtime pieces made
  int broken_bonds = 0;                          ///< bonds broken by the end
  int falling_clusters = 0;                      ///< clusters that fell
  int bodies = 0;                                ///< physics bodies at the end
  SolverReport solver;                           ///< stress solves summed
  std::optional<InstructionCounts> instructions; ///< instruction mode only
  double latency_ms = 0.0;                       ///< trigger to visible at 60 Hz, the slowest event (EventLatency::ms)
  int latency_frames = 0;                        ///< its frames, trigger to visible, both counted
  int latency_after_impact_frames = 0;           ///< its frames from the impact to visible
  int trigger_frame = -1;                        ///< its trigger frame (-1: nothing became visible)
  int visible_frame = -1;                        ///< its visible frame
  int event_steps = 0;                           ///< event steps run (docs/pipeline.md section 6)
  double largest_step_ms = 0.0;                  ///< the largest event step
  double worst_work_ms = 0.0;                    ///< the most event work done in one frame
  int bodies_peak = 0;                           ///< most bodies in the world at the end of a frame
  int faded = 0;                                 ///< runtime pieces removed by the fade-out
  int particles_spawned = 0;                     ///< debris particles spawned
  int particles_peak = 0;                        ///< most particles alive at the end of a frame
};

/// Worst error figures over a cell's repetitions.
struct CellError {
  double prefracture_volume_error = 0.0;
  double prefracture_partition_error = 0.0;
  bool prefracture_all_closed = true;
  double prefracture_min_fragment_volume = 0.0;
  double runtime_volume_error = 0.0;
  double runtime_partition_error = 0.0;
  bool runtime_all_closed = true;
  double runtime_min_fragment_volume = 0.0;
  bool solver_converged = true;
  double solver_residual = 0.0;
};

/// One cell: its settings, raw samples and summary.
struct GridCell {
  int prefracture = 0;                 ///< requested pre-fracture fragments
  int runtime = 0;                     ///< requested runtime fragments per hit fragment
  std::string prefracturer;            ///< pre-fracture algorithm
  std::string fracturer;               ///< runtime algorithm
  std::string stress;                  ///< stress model
  std::vector<GridSample> samples;     ///< one per repetition
  double worst_frame_ms = 0.0;         ///< median over repetitions of each one's slowest frame
  SampleStatistics frame_ms;           ///< over every frame of every repetition
  double event_ms = 0.0;               ///< median over repetitions of the event frame
  StageTimes stages_ms{};              ///< per stage, median over repetitions (inside frames)
  StageTimes setup_ms{};               ///< per stage, median over repetitions (offline)
  CellError error;                     ///< worst over repetitions
  std::vector<std::string> stages_run; ///< union over repetitions, in data-flow order
  std::vector<StageSkip> stages_skipped;  ///< union over repetitions, first seen first
  bool within_budget = true;           ///< worst_frame_ms <= budget
  std::string schedule = "immediate";  ///< schedule mode of the runs
  double latency_ms = 0.0;             ///< median over repetitions of latency_ms
  double latency_frames = 0.0;         ///< median over repetitions of latency_frames
  double bodies = 0.0;                 ///< median over repetitions of the bodies at the end
  double bodies_peak = 0.0;            ///< median over repetitions of bodies_peak
  double particles_peak = 0.0;         ///< median over repetitions of particles_peak
  double largest_step_ms = 0.0;        ///< largest event step over repetitions
  bool within_latency_budget = true;   ///< latency_ms <= latency budget
  /// Why the cell has no results ("timeout after 2 s", "crashed: signal 11 (Segmentation fault)"),
  /// empty when it ran. A failed cell has no samples and is neither within budget nor within latency.
  std::string failed;
};

/// A whole grid.
struct GridResult {
  double budget_ms = 0.0;              ///< the budget the cells were judged against
  double latency_budget_ms = 50.0;     ///< the latency budget the cells were judged against
  int repetitions = 0;                 ///< runs per cell
  int frames = 0;                      ///< frames per run
  bool no_skip = false;                ///< automatic skips were off
  bool same_seed = false;              ///< every repetition used the same seed
  std::vector<GridCell> cells;         ///< pre-fracture major, runtime minor
  double wall_s = 0.0;                 ///< wall time of the whole grid, s
  std::string metric = "time";         ///< "time", or "instructions" when samples carry instruction counts
  int shard_index = 0;                 ///< which shard this is (see GridOptions)
  int shard_count = 1;                 ///< of how many
  double cell_timeout_s = 0.0;         ///< wall-time limit per cell, s (0: none)

  /// True when every cell ran, is within the frame budget and the latency budget, and its fractures
  /// pass their result checks (cell_checks.h).
  [[nodiscard]] bool passed() const;
};

/// Checks `options` against `c` before anything runs: algorithm names exist (errors name the flag or
/// the case key), counts >= 1, budget finite and > 0, repetitions and frames >= 1, the cell timeout
/// finite and >= 0, and the limits of harness/limits.h (repetitions, frames, fragment counts, cells,
/// pieces per run, frames recorded).
Status check_grid_options(const Case& c, const GridOptions& options);

/// The cell `p` x `r` of a grid with `options`, its settings filled in and nothing run: what a cell
/// that failed reports.
GridCell grid_cell_settings(const Case& c, const GridOptions& options, int p, int r);

/// Runs one cell of the grid, every repetition in this process, passing `verdicts` (clean
/// self-intersection verdicts the grid shares between its cells, or none) to every run. `done` counts
/// the runs finished (for `options.progress`, out of `total`).
Result<GridCell> run_grid_cell(const PreparedCase& prepared, const GridOptions& options, int p, int r,
                               SelfIntersectionVerdicts* verdicts, int& done, int total);

/// Fills `cell`'s schedule summary (latency, bodies, particles: medians over its samples) and judges
/// its latency against `latency_budget_ms`.
void summarise_schedule(GridCell& cell, double latency_budget_ms);

/// Fills every summary of `cell` from its samples (frame statistics, medians over repetitions, the
/// schedule summary) and judges it against `budget_ms` and `latency_budget_ms`.
void summarise_cell(GridCell& cell, double budget_ms, double latency_budget_ms);

/// Makes `into` the worst of the two error figures (as if their repetitions had been one cell's).
void add_cell_error(CellError& into, const CellError& other);

/// Adds the stage names `run` (kept in data-flow order, each once) and the skips `skipped` (each stage
/// and reason once, first seen first) to `cell`'s lists.
void add_cell_stages(GridCell& cell, const std::vector<std::string>& run, const std::vector<StageSkip>& skipped);

/// Runs the grid of `prepared` (options checked by check_grid_options).
Result<GridResult> run_grid(const PreparedCase& prepared, const GridOptions& options);

}  // namespace shatter
