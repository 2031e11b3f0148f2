#pragma once
/// The stage times of every frame of a run (docs/results.md, `frame_stages_ms`): what each frame was
/// made of, so that a frame that breaks the budget can be taken apart, not only the run's totals.
///
/// Design note: kept per stage, not per frame. Most stages run in a few frames only (the event's), a
/// run writes one array per stage that took time, and a stage that took none in any frame holds
/// nothing; one frame's breakdown is a column across the stages (stage_times_in_frame). Values are
/// the wall clock's own (whole nanoseconds, in ms), so the frames of a stage add up to its total.

#include "harness/results/stage_times.h"

#include <cstddef>
#include <vector>

namespace shatter {

/// Per stage, its wall time in each frame of a run, ms: empty when the stage took no time in any
/// frame, else one value (>= 0) per frame.
using FrameStageTimes = std::array<std::vector<double>, kStageCount>;

/// The stage times of frame `frame`, ms (0 for a stage without values).
[[nodiscard]] StageTimes stage_times_in_frame(const FrameStageTimes& times, std::size_t frame);

/// Per stage, the sum over the frames, ms.
[[nodiscard]] StageTimes sum_over_frames(const FrameStageTimes& times);

/// `ms` rounded to the wall clock's resolution, 1 ns (1e-6 ms): a difference of two running sums of
/// clock readings is a whole number of nanoseconds up to round-off, and is written as one.
[[nodiscard]] double round_to_clock_ms(double ms);

}  // namespace shatter
