// The runtime event's phase sequence per route, and the events of a case in landing order.

#include "harness/pipeline/event/runtime_event.h"

#include <catch2/catch.hpp>

#include <vector>

namespace {

using namespace shatter;

std::vector<EventPhase> sequence(const EventRoute& route) {
  std::vector<EventPhase> out;
  for (EventPhase p = EventPhase::fracture; p != EventPhase::done; p = phase_after(p, route)) {
    out.push_back(p);
    REQUIRE(out.size() < kEventPhaseCount);
  }
  return out;
}

ImpactEvent impact_at(int frame, double x) {
  ImpactEvent e;
  e.frame = frame;
  e.impact.point = Vec3(x, 0, 0);
  return e;
}

}  // namespace

TEST_CASE("runtime event: the phases run in data-flow order, passing over what the run lacks", "[pipeline][event]") {
  using P = EventPhase;
  REQUIRE(sequence({true, true}) ==
          std::vector<P>{P::fracture, P::bond_update, P::stress, P::falling_clusters, P::colliders, P::make_visible});
  REQUIRE(sequence({true, false}) ==
          std::vector<P>{P::fracture, P::bond_update, P::stress, P::falling_clusters, P::make_visible});
  REQUIRE(sequence({false, true}) == std::vector<P>{P::fracture, P::bond_update, P::colliders, P::make_visible});
  REQUIRE(sequence({false, false}) == std::vector<P>{P::fracture, P::bond_update, P::make_visible});
  REQUIRE(phase_after(P::done, {}) == P::done);
}

TEST_CASE("runtime event: events in landing order, clamped to the last frame, triggers by schedule",
          "[pipeline][event]") {
  const std::vector<ImpactEvent> impacts = {impact_at(7, 1.0), impact_at(3, 2.0), impact_at(9, 3.0)};
  const std::vector<RuntimeEvent> immediate = events_in_landing_order(impacts, 6, ScheduleMode::immediate, 2);
  REQUIRE(immediate.size() == 3);
  // Frame 3 first; 7 and 9 both land in the last frame (5) and keep their file order.
  REQUIRE(immediate[0].impact == &impacts[1].impact);
  REQUIRE(immediate[1].impact == &impacts[0].impact);
  REQUIRE(immediate[2].impact == &impacts[2].impact);
  for (int i = 0; i < 3; ++i) {
    REQUIRE(immediate[static_cast<std::size_t>(i)].index == i);
    REQUIRE(immediate[static_cast<std::size_t>(i)].trigger_frame == immediate[static_cast<std::size_t>(i)].impact_frame);
    REQUIRE(immediate[static_cast<std::size_t>(i)].phase == EventPhase::fracture);
    REQUIRE(immediate[static_cast<std::size_t>(i)].visible_frame == -1);
  }
  REQUIRE(immediate[0].impact_frame == 3);
  REQUIRE(immediate[1].impact_frame == 5);

  const std::vector<RuntimeEvent> prefetch = events_in_landing_order(impacts, 6, ScheduleMode::prefetch, 4);
  REQUIRE(prefetch[0].trigger_frame == 0);  // 3 - 4, not before frame 0
  REQUIRE(prefetch[1].trigger_frame == 1);
  REQUIRE(prefetch[1].impact_frame == 5);
}
