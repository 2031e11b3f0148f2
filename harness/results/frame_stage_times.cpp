#include "harness/results/frame_stage_times.h"

#include <cmath>

namespace shatter {

StageTimes stage_times_in_frame(const FrameStageTimes& times, std::size_t frame) {
  StageTimes out{};
  for (std::size_t s = 0; s < kStageCount; ++s)
    if (frame < times[s].size()) out[s] = times[s][frame];
  return out;
}

StageTimes sum_over_frames(const FrameStageTimes& times) {
  StageTimes out{};
  for (std::size_t s = 0; s < kStageCount; ++s)
    for (const double ms : times[s]) out[s] += ms;
  return out;
}

double round_to_clock_ms(double ms) {
  const double rounded = std::round(ms * 1e6) / 1e6;
  return rounded == 0.0 ? 0.0 : rounded;  // no -0 from a round-off below zero
}

}  // namespace shatter
