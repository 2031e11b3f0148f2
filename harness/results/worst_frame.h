#pragma once
/// What the worst frame was made of: a repetition's slowest frame and its stage times, and the one a
/// cell reports (docs/results.md, `worst_frame_stages_ms`). The gate is on the worst frame; this says
/// which stages it was spent in, which the run's stage totals cannot (physics may dominate the totals
/// while the runtime fracture is most of the worst frame).

#include "harness/results/grid_record.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace shatter {

/// One repetition's slowest frame.
struct WorstFrame {
  int repetition = -1;  ///< index of the sample in its cell
  int frame = -1;       ///< index of the frame in the sample's frame_ms
  double ms = 0.0;      ///< its wall time, ms
  StageTimes stages{};  ///< its stage times (wall), ms
};

/// Index of the largest value of `frame_ms` (the first of equal ones), -1 when empty.
[[nodiscard]] int slowest_frame(const std::vector<double>& frame_ms);

/// The slowest frame of `sample` (repetition `repetition` of its cell); nullopt when the sample has no
/// frames or no per-frame stage times (a file from before them).
[[nodiscard]] std::optional<WorstFrame> sample_worst_frame(const GridSample& sample, int repetition);

/// The slowest frame of the repetition whose slowest frame is the median one of `cell` (of an even
/// number, the lower of the two middle ones; equal times in repetition order): the cell's
/// `worst_frame_ms` is that frame's time for an odd number of repetitions. Nullopt for a cell without
/// samples, or when that repetition has no per-frame stage times.
[[nodiscard]] std::optional<WorstFrame> cell_worst_frame(const GridCell& cell);

/// The stages of `stages` with time > 0, largest first (equal times in data-flow order), at most `count`.
[[nodiscard]] std::vector<std::pair<Stage, double>> largest_stages(const StageTimes& stages, std::size_t count);

}  // namespace shatter
