#include "harness/pipeline/event/runtime_event.h"

#include <algorithm>
#include <utility>

namespace shatter {

EventPhase phase_after(EventPhase phase, const EventRoute& route) {
  const EventPhase after_structure = route.world ? EventPhase::colliders : EventPhase::make_visible;
  switch (phase) {
    case EventPhase::fracture: return EventPhase::bond_update;
    case EventPhase::bond_update: return route.bonds ? EventPhase::stress : after_structure;
    case EventPhase::stress: return EventPhase::falling_clusters;
    case EventPhase::falling_clusters: return after_structure;
    case EventPhase::colliders: return EventPhase::make_visible;
    case EventPhase::make_visible:
    case EventPhase::done: return EventPhase::done;
  }
  return EventPhase::done;
}

std::vector<RuntimeEvent> events_in_landing_order(const std::vector<ImpactEvent>& impacts, int frames,
                                                  ScheduleMode mode, int prefetch_frames) {
  std::vector<RuntimeEvent> events;
  for (const ImpactEvent& e : impacts) {
    RuntimeEvent p;
    p.impact = &e.impact;
    p.impact_frame = std::min(e.frame, frames - 1);
    p.trigger_frame = mode == ScheduleMode::prefetch ? std::max(0, p.impact_frame - prefetch_frames) : p.impact_frame;
    events.push_back(std::move(p));
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const RuntimeEvent& a, const RuntimeEvent& b) { return a.impact_frame < b.impact_frame; });
  for (std::size_t i = 0; i < events.size(); ++i) events[i].index = static_cast<int>(i);
  return events;
}

}  // namespace shatter
