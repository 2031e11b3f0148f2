// Latency of one event from its frames: paced at 60 Hz, and nothing for an event that stayed invisible.

#include "harness/pipeline/schedule/event_latency.h"

#include <catch2/catch.hpp>

namespace {

using namespace shatter;

}  // namespace

TEST_CASE("latency: frames within the period count 1/60 s each, exactly, a long frame counts its time",
          "[pipeline][schedule]") {
  const std::vector<double> frame_ms = {3.0, 16.0, 2.5, 25.0, 1.0};
  REQUIRE(paced_ms(frame_ms, 0, 2) == 50.0);
  REQUIRE(paced_ms(frame_ms, 2, 3) == Approx(1000.0 / 60.0 + 25.0));
  REQUIRE(paced_ms(frame_ms, 4, 4) == Approx(1000.0 / 60.0));
}

TEST_CASE("latency: trigger to visible, both counted, an event that fractured nothing has none",
          "[pipeline][schedule]") {
  const std::vector<double> frame_ms(10, 1.0);
  RuntimeEvent e;
  e.trigger_frame = 2;
  e.impact_frame = 4;
  e.visible_frame = 5;
  const EventLatency l = event_latency(e, frame_ms);
  REQUIRE(l.frames == 4);
  REQUIRE(l.after_impact == 1);
  REQUIRE(l.ms == Approx(4000.0 / 60.0));

  e.visible_frame = -1;
  const EventLatency none = event_latency(e, frame_ms);
  REQUIRE(none.visible_frame == -1);
  REQUIRE(none.trigger_frame == 2);
  REQUIRE(none.frames == 0);
  REQUIRE(none.ms == 0.0);
}
