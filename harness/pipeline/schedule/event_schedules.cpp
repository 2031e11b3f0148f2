#include "harness/pipeline/schedule/event_schedules.h"

namespace shatter {

Status run_immediate(EventQueue& queue, int frame, const EventStepper& step) {
  while (!queue.empty() && queue.front()->impact_frame <= frame) {
    while (queue.front()->phase != EventPhase::done)
      if (Result<double> ms = step(*queue.front()); !ms) return ms.error();
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
