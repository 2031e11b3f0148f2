#pragma once
/// When a runtime event's result took part in the world, counted from its trigger (docs/pipeline.md
/// section 6, "Latency").

#include "harness/pipeline/destruction_run.h"
#include "harness/pipeline/event/runtime_event.h"

#include <vector>

namespace shatter {

/// Frames `first` to `last` (both counted) as a player at 60 Hz sees them: each lasts max(its wall time
/// in `frame_ms`, 1/60 s), ms. Summed in units of 1/60 ms so that frames within the period add up
/// exactly (3 frames: 50 ms, not 50.000000000000007).
double paced_ms(const std::vector<double>& frame_ms, int first, int last);

/// The latency of `event` after the run, with `frame_ms` the wall time of every frame (ms); frames,
/// lag and ms stay 0 when the event fractured nothing.
EventLatency event_latency(const RuntimeEvent& event, const std::vector<double>& frame_ms);

}  // namespace shatter
