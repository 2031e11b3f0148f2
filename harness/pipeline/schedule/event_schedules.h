#pragma once
/// The schedules of the runtime event (docs/pipeline.md section 6), one function per mode: which
/// steps of the triggered events run in one frame. A schedule only decides when a step runs; the step
/// itself (event/event_phases.h) is given as a function, so a schedule can be run on hand-made events.

#include "algorithms/core/result.h"
#include "harness/cases/case.h"
#include "harness/pipeline/event/runtime_event.h"

#include <deque>
#include <functional>

namespace shatter {

/// The triggered events not yet done, in landing order (borrowed).
using EventQueue = std::deque<RuntimeEvent*>;

/// Runs one step of an event (advancing its phase) and returns the step's wall time in ms, or its error.
using EventStepper = std::function<Result<double>(RuntimeEvent&)>;

/// `immediate`: every queued event whose impact has landed (impact frame <= `frame`) runs to the end,
/// in order, and leaves the queue. An event that waits for a later frame (RuntimeEvent::waits_until:
/// its new bodies capped per frame) stops there, and the events after it wait with it.
Status run_immediate(EventQueue& queue, int frame, const EventStepper& step);

/// `prefetch`: every queued event's fracture runs now (the projectile is in flight); then as
/// run_immediate: the rest of each event when its impact lands.
Status run_prefetch(EventQueue& queue, int frame, const EventStepper& step);

/// `amortized`: the steps of landed events in order, at least one a frame, no step started once the
/// frame's step time reaches `work_budget_ms` (ms): a frame spends at most the budget plus one step.
/// In the `last_frame` of the run, everything left runs. Finished events leave the queue; an event that
/// waits for a later frame ends the frame's steps.
Status run_amortized(EventQueue& queue, int frame, bool last_frame, double work_budget_ms, const EventStepper& step);

/// The schedule `mode` (with `spec`'s work budget) for one frame.
Status run_schedule(ScheduleMode mode, const ScheduleSpec& spec, EventQueue& queue, int frame, bool last_frame,
                    const EventStepper& step);

}  // namespace shatter
