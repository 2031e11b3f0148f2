// The schedule functions alone, on hand-made events and a stepper that only advances the phase and
// reports a fixed step time: which steps run in which frame, the amortized budget, the queue.

#include "harness/pipeline/schedule/event_schedules.h"

#include <catch2/catch.hpp>

#include <vector>

namespace {

using namespace shatter;

/// Six steps per event (one per phase, bonds and a world on the route); each "takes" `ms`.
struct FakeStepper {
  double ms = 0.4;
  std::vector<std::pair<int, EventPhase>> log;  // (event index, phase it ran)

  EventStepper stepper() {
    return [this](RuntimeEvent& e) -> Result<double> {
      log.emplace_back(e.index, e.phase);
      e.phase = phase_after(e.phase, EventRoute{});
      return ms;
    };
  }
};

RuntimeEvent event(int index, int impact_frame, int trigger_frame) {
  RuntimeEvent e;
  e.index = index;
  e.impact_frame = impact_frame;
  e.trigger_frame = trigger_frame;
  return e;
}

constexpr int kStepsPerEvent = 6;

}  // namespace

TEST_CASE("schedule/immediate: a landed event runs to the end in one frame, a later one waits",
          "[pipeline][schedule]") {
  RuntimeEvent a = event(0, 5, 5);
  RuntimeEvent b = event(1, 7, 7);
  EventQueue queue{&a, &b};
  FakeStepper fake;
  REQUIRE(run_immediate(queue, 4, fake.stepper()));
  REQUIRE(fake.log.empty());
  REQUIRE(run_immediate(queue, 5, fake.stepper()));
  REQUIRE(fake.log.size() == kStepsPerEvent);
  REQUIRE(a.phase == EventPhase::done);
  REQUIRE(b.phase == EventPhase::fracture);
  REQUIRE(queue.size() == 1);
  REQUIRE(queue.front() == &b);
}

TEST_CASE("schedule/prefetch: every queued event fractures at once, the rest waits for its impact",
          "[pipeline][schedule]") {
  FakeStepper fake;
  SECTION("one event: the fracture in the trigger frame, nothing until the impact, the rest then") {
    RuntimeEvent a = event(0, 5, 3);
    EventQueue queue{&a};
    REQUIRE(run_prefetch(queue, 3, fake.stepper()));
    REQUIRE(fake.log == std::vector<std::pair<int, EventPhase>>{{0, EventPhase::fracture}});
    REQUIRE(a.phase == EventPhase::bond_update);
    REQUIRE(run_prefetch(queue, 4, fake.stepper()));
    REQUIRE(fake.log.size() == 1);
    REQUIRE(run_prefetch(queue, 5, fake.stepper()));
    REQUIRE(fake.log.size() == kStepsPerEvent);
    REQUIRE(queue.empty());
  }
  SECTION("two events: both fracture before the landed one finishes; the other keeps waiting") {
    RuntimeEvent a = event(0, 5, 3);
    RuntimeEvent b = event(1, 8, 5);
    EventQueue queue{&a, &b};
    REQUIRE(run_prefetch(queue, 5, fake.stepper()));
    REQUIRE(fake.log.size() == kStepsPerEvent + 1);
    REQUIRE(fake.log[0] == std::make_pair(0, EventPhase::fracture));
    REQUIRE(fake.log[1] == std::make_pair(1, EventPhase::fracture));
    REQUIRE(fake.log[2] == std::make_pair(0, EventPhase::bond_update));
    REQUIRE(a.phase == EventPhase::done);
    REQUIRE(b.phase == EventPhase::bond_update);
    REQUIRE(queue.size() == 1);
    REQUIRE(queue.front() == &b);
  }
}

TEST_CASE("schedule/amortized: steps stop once the frame's work reaches the budget, the last frame finishes",
          "[pipeline][schedule]") {
  FakeStepper fake;  // 0.4 ms a step
  SECTION("budget 1 ms: three steps a frame (0.4, 0.8 then 1.2 >= 1)") {
    RuntimeEvent a = event(0, 2, 2);
    EventQueue queue{&a};
    REQUIRE(run_amortized(queue, 2, false, 1.0, fake.stepper()));
    REQUIRE(fake.log.size() == 3);
    REQUIRE(a.phase == EventPhase::falling_clusters);
    REQUIRE(run_amortized(queue, 3, false, 1.0, fake.stepper()));
    REQUIRE(fake.log.size() == kStepsPerEvent);
    REQUIRE(queue.empty());
  }
  SECTION("a budget reached exactly stops the frame: 0.4 + 0.4 >= 0.8, two steps") {
    RuntimeEvent a = event(0, 2, 2);
    EventQueue queue{&a};
    REQUIRE(run_amortized(queue, 2, false, 0.8, fake.stepper()));
    REQUIRE(fake.log.size() == 2);
  }
  SECTION("budget 0: one step a frame; nothing before the impact") {
    RuntimeEvent a = event(0, 2, 2);
    EventQueue queue{&a};
    REQUIRE(run_amortized(queue, 1, false, 0.0, fake.stepper()));
    REQUIRE(fake.log.empty());
    for (int frame = 2; frame < 2 + kStepsPerEvent; ++frame) {
      REQUIRE(run_amortized(queue, frame, false, 0.0, fake.stepper()));
      REQUIRE(fake.log.size() == static_cast<std::size_t>(frame - 1));
    }
    REQUIRE(queue.empty());
  }
  SECTION("the last frame runs every step left, of every landed event") {
    RuntimeEvent a = event(0, 2, 2);
    RuntimeEvent b = event(1, 2, 2);
    EventQueue queue{&a, &b};
    REQUIRE(run_amortized(queue, 2, true, 0.0, fake.stepper()));
    REQUIRE(fake.log.size() == 2 * kStepsPerEvent);
    REQUIRE(queue.empty());
  }
}

TEST_CASE("schedule: a failing step stops the schedule with its error", "[pipeline][schedule]") {
  RuntimeEvent a = event(0, 0, 0);
  const EventStepper failing = [](RuntimeEvent&) -> Result<double> { return Error{"case: runtime fracture at frame 0"}; };
  for (const ScheduleMode mode : {ScheduleMode::immediate, ScheduleMode::prefetch, ScheduleMode::amortized}) {
    EventQueue queue{&a};
    const Status s = run_schedule(mode, ScheduleSpec{}, queue, 0, false, failing);
    INFO(schedule_mode_name(mode));
    REQUIRE_FALSE(s);
    REQUIRE(s.error().message == "case: runtime fracture at frame 0");
  }
}
