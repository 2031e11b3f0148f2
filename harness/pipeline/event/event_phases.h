#pragma once
/// The phases of a runtime event (docs/pipeline.md section 6), one function each, run one indivisible
/// step at a time. Every schedule runs the same steps on the same data in the same order; only the
/// frames they run in differ (schedule/event_schedules.h).

#include "algorithms/core/result.h"
#include "harness/pipeline/event/runtime_event.h"
#include "harness/pipeline/run_state.h"

namespace shatter {

/// Pieces prepared as colliders per step of the colliders phase (per worker thread under `amortized`;
/// with several threads the other schedules take all pieces in one step: RunOptions::threads).
inline constexpr std::size_t kColliderBatch = 4;

/// The route `run`'s events take through the phases (bonds and a physics world or not).
EventRoute event_route(const RunState& run);

/// Runs one step of `event`'s current phase in `run` (frame `run.frame`), timing its stages into
/// RunResult::frame_stages and moving the event to its next phase when the phase is finished. A `done`
/// event is left as it is. Errors name the case and the frame of a failed runtime fracture or solve.
Status run_event_step(RunState& run, RuntimeEvent& event);

}  // namespace shatter
