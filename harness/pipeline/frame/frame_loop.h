#pragma once
/// The frames of a destruction run (docs/pipeline.md section 1): `frames` frames of 1/60 s, each
/// running the scheduled steps of the runtime events, the fade-out, one physics step and the debris
/// particles, and each timed as a whole (wall and thread CPU time) and per stage.

#include "algorithms/core/result.h"
#include "harness/pipeline/event/runtime_event.h"
#include "harness/pipeline/run_state.h"

#include <vector>

namespace shatter {

/// Runs `frames` frames of `run` (after its setup) with `events` (landing order, see
/// events_in_landing_order) under the schedule RunResult::schedule. Fills the per-frame records of
/// RunResult (frame_ms, frame_cpu_ms, frame_stage_ms, frame_work_ms, frame_bodies, frame_particles,
/// event_frames, event_ms, step_ms, largest_step_ms, the peaks) and each event's visible frame.
/// Creates the debris field when the case has debris. With RunOptions::recorder, records every body
/// after each frame, outside its time. Errors are those of the event steps and the recorder's limit.
Status run_frames(RunState& run, std::vector<RuntimeEvent>& events, int frames);

}  // namespace shatter
