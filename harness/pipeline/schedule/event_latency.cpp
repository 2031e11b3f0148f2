#include "harness/pipeline/schedule/event_latency.h"

#include <algorithm>

namespace shatter {

double paced_ms(const std::vector<double>& frame_ms, int first, int last) {
  double sixtieths = 0.0;
  for (int f = first; f <= last; ++f) sixtieths += std::max(frame_ms[static_cast<std::size_t>(f)] * 60.0, 1000.0);
  return sixtieths / 60.0;
}

EventLatency event_latency(const RuntimeEvent& event, const std::vector<double>& frame_ms) {
  EventLatency l;
  l.trigger_frame = event.trigger_frame;
  l.impact_frame = event.impact_frame;
  l.visible_frame = event.visible_frame;
  if (event.visible_frame >= 0) {
    l.frames = event.visible_frame - event.trigger_frame + 1;
    l.after_impact = event.visible_frame - event.impact_frame;
    l.ms = paced_ms(frame_ms, event.trigger_frame, event.visible_frame);
  }
  return l;
}

}  // namespace shatter
