#pragma once
/// What a grid run produces (DESIGN.md section 8; schema in docs/results.md): per cell its settings,
/// one sample per repetition and the cell's summaries and verdicts. Written by the grid runner, read
/// back from results files, merged, compared and reported; every writer and reader works on these
/// types, so they sit below the grid and the results code alike.
///
/// Design note: a sample keeps its timings typed (every frame, stage times, the event frame, CPU time
/// and calibration): the figures the gate, compare and report read by type. Every other figure of a
/// run is a named entry of its record (figure_record.h, the list in run_figures.h), which every
/// output writes without code of its own for that figure.

#include "harness/results/figure_record.h"
#include "harness/results/frame_stage_times.h"
#include "harness/results/recorded_frames.h"
#include "harness/results/run_figures.h"
#include "harness/results/sample_statistics.h"
#include "harness/results/stage_times.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shatter {

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
  std::vector<double> frame_ms;                  ///< every frame, ms
  double event_ms = 0.0;                         ///< the first event frame, ms
  int event_frame = -1;                          ///< its index (-1: no impact landed)
  double worst_frame_ms = 0.0;                   ///< the slowest frame, ms
  StageTimes stages_ms{};                        ///< stage times inside frames, ms
  /// Every frame's stage times (wall), ms: each stage's values add up to its stages_ms; nullopt in a
  /// file written before they were kept.
  std::optional<FrameStageTimes> frame_stages_ms;
  StageTimes setup_ms{};                         ///< offline stage times, ms
  StageTimes stages_cpu_ms{};                    ///< thread CPU time of the stages inside frames, ms
  double worst_frame_cpu_ms = 0.0;               ///< thread CPU time of the frame with the most of it, ms
  double calibration_ms = 0.0;                   ///< the reference workload's CPU time around this run (calibration.h), ms; 0 unknown
  FigureRecord figures = run_figure_defaults();  ///< every other figure of the run (run_figures.h)
  std::optional<InstructionCounts> instructions; ///< instruction mode only
};

/// The worst accuracy figures of a cell's fractures and stress solves over its repetitions.
struct CellAccuracy {
  double prefracture_volume_error = 0.0;         ///< largest |sum V_i - V| / V of the pre-fracture
  double prefracture_partition_error = 0.0;      ///< largest partition error of the pre-fracture
  bool prefracture_all_closed = true;            ///< every pre-fracture fragment closed, in every repetition
  double prefracture_min_fragment_volume = 0.0;  ///< smallest pre-fracture fragment, m^3
  double runtime_volume_error = 0.0;             ///< largest volume error of the runtime fractures
  double runtime_partition_error = 0.0;          ///< largest partition error of the runtime fractures
  bool runtime_all_closed = true;                ///< every runtime piece closed, in every repetition
  double runtime_min_fragment_volume = 0.0;      ///< smallest runtime piece, m^3 (0: no runtime pieces)
  bool solver_converged = true;                  ///< every stress solve converged
  double solver_residual = 0.0;                  ///< largest relative residual of a stress solve
};

/// One cell: its settings, raw samples, summaries and verdicts.
struct GridCell {
  int prefracture = 0;                 ///< requested pre-fracture fragments
  int runtime = 0;                     ///< requested runtime fragments per hit fragment
  std::string prefracturer;            ///< pre-fracture algorithm
  std::string fracturer;               ///< runtime algorithm
  std::string stress;                  ///< stress model
  std::vector<GridSample> samples;     ///< one per repetition
  double worst_frame_ms = 0.0;         ///< median over repetitions of each one's slowest frame, ms
  SampleStatistics frame_ms;           ///< over every frame of every repetition, ms
  double event_ms = 0.0;               ///< median over repetitions of the event frame, ms
  StageTimes stages_ms{};              ///< per stage, median over repetitions (inside frames), ms
  StageTimes setup_ms{};               ///< per stage, median over repetitions (offline), ms
  CellAccuracy accuracy;               ///< worst over repetitions
  std::vector<std::string> stages_run; ///< union over repetitions, in data-flow order
  std::vector<StageSkip> stages_skipped;  ///< union over repetitions, first seen first
  bool within_budget = true;           ///< worst_frame_ms <= budget
  std::string schedule = "immediate";  ///< schedule mode of the runs
  FigureRecord summaries;              ///< the samples' figures summarised (summarise_figures)
  bool within_latency_budget = true;   ///< the `latency_ms` summary <= latency budget
  /// Why the cell has no results ("timeout after 2 s", "crashed: signal 11 (Segmentation fault)"),
  /// empty when it ran. A failed cell has no samples and is neither within budget nor within latency.
  std::string failed;
  /// Wall time the cell took, every repetition and its setup (the JUnit test's time), s; 0 when not
  /// measured (a cell read back from results).
  double wall_s = 0.0;
  /// Its first repetition recorded for playback (`grid --record-frames`); written to the sidecar, not
  /// to the JSON, so a cell read back from results has none.
  std::optional<RecordedFrames> recording;
};

/// A whole grid.
struct GridResult {
  double budget_ms = 0.0;              ///< the budget the cells were judged against, ms
  double latency_budget_ms = 50.0;     ///< the latency budget the cells were judged against, ms
  int repetitions = 0;                 ///< runs per cell
  int frames = 0;                      ///< frames per run
  bool no_skip = false;                ///< automatic skips were off
  int threads = 1;                     ///< threads of each runtime event (grid --threads)
  bool same_seed = false;              ///< every repetition used the same seed
  std::vector<GridCell> cells;         ///< pre-fracture major, runtime minor
  double wall_s = 0.0;                 ///< wall time of the whole grid, s
  std::string metric = "time";         ///< "time", or "instructions" when samples carry instruction counts
  int shard_index = 0;                 ///< which shard this is (`grid --shard K/N`)
  int shard_count = 1;                 ///< of how many
  double cell_timeout_s = 0.0;         ///< wall-time limit per cell, s (0: none)
  /// Where the cells' recordings were written (the sidecar beside the JSON, as the JSON names it) and
  /// its size in bytes; empty when nothing was recorded. The results JSON's `recorded_frames` block.
  std::string recorded_frames_file;
  std::uint64_t recorded_frames_bytes = 0;  ///< size of that file, bytes

  /// True when every cell ran, is within the frame budget and the latency budget, and its fractures
  /// pass their result checks (cell_checks.h).
  [[nodiscard]] bool passed() const;
};

}  // namespace shatter
