#include "harness/pipeline/schedule/event_schedules.h"

namespace shatter {

Status run_immediate(EventQueue& queue, int frame, const EventStepper& step) {
  while (!queue.empty() && queue.front()->impact_frame <= frame) {
    RuntimeEvent& e = *queue.front();
    while (e.phase != EventPhase::done && e.waits_until <= frame)
      if (Result<double> ms = step(e); !ms) return ms.error();
    if (e.phase != EventPhase::done) return {};  // it goes on in a later frame; the events after it wait
    queue.pop_front();
  }
  return {};
}

Status run_prefetch(EventQueue& queue, int frame, const EventStepper& step) {
  for (RuntimeEvent* e : queue)
    while (e->phase == EventPhase::fracture)
      if (Result<double> ms = step(*e); !ms) return ms.error();
  return run_immediate(queue, frame, step);
}

Status run_amortized(EventQueue& queue, int frame, bool last_frame, double work_budget_ms, const EventStepper& step) {
  double spent = 0.0;  // ms of steps run in this frame
  bool first = true;
  while (!queue.empty() && queue.front()->impact_frame <= frame) {
    if (!first && !last_frame && spent >= work_budget_ms) break;
    if (queue.front()->waits_until > frame) break;
    Result<double> ms = step(*queue.front());
    if (!ms) return ms.error();
    spent += *ms;
    first = false;
    if (queue.front()->phase == EventPhase::done) queue.pop_front();
  }
  return {};
}

Status run_schedule(ScheduleMode mode, const ScheduleSpec& spec, EventQueue& queue, int frame, bool last_frame,
                    const EventStepper& step) {
  switch (mode) {
    case ScheduleMode::immediate: return run_immediate(queue, frame, step);
    case ScheduleMode::prefetch: return run_prefetch(queue, frame, step);
    case ScheduleMode::amortized: return run_amortized(queue, frame, last_frame, spec.work_budget_ms, step);
  }
  return {};
}

}  // namespace shatter
