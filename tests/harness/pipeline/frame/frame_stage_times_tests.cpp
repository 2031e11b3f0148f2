// Per-frame stage times of whole runs obey the conservation laws: each stage's frames add up to its
// total inside frames, and a frame's stages add up to no more than the frame's wall time; under every
// schedule, with fade-out and debris (every stage a frame can hold).

#include "harness/pipeline/destruction_run.h"
#include "harness/results/frame_stage_times.h"
#include "tests/support/builtin_registries.h"
#include "tests/support/prepared_case.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

using namespace shatter;

using test::prepared;

/// Allowed excess of a frame's stages over its wall time, ms: values are whole nanoseconds, so only
/// the round-off of adding them up.
constexpr double kFrameSlackMs = 1e-9;

RunResult run(const PreparedCase& p, ScheduleMode mode) {
  RunOptions o;
  o.partition_samples = 0;
  o.frames = 40;
  o.prefracture_fragments = 30;
  o.runtime_fragments = 10;
  o.schedule = mode;
  Result<RunResult> r = run_destruction(p, o, test::builtin_registries());
  INFO((r ? std::string() : r.error().message));
  REQUIRE(r);
  return std::move(*r);
}

void require_conserved(const RunResult& r) {
  const std::size_t frames = r.frame_ms.size();
  const StageTimes sums = sum_over_frames(r.frame_stage_ms);
  for (const Stage s : kAllStages) {
    const auto k = static_cast<std::size_t>(s);
    INFO(stage_name(s));
    const std::vector<double>& column = r.frame_stage_ms[k];
    REQUIRE((column.empty() || column.size() == frames));
    REQUIRE(std::all_of(column.begin(), column.end(), [](double ms) { return ms >= 0.0; }));
    const double total = r.frame_stages.wall[k];
    REQUIRE(std::abs(sums[k] - total) <= 1e-6 * total);
    REQUIRE(column.empty() == (total == 0.0));
  }
  for (std::size_t f = 0; f < frames; ++f) {
    const StageTimes t = stage_times_in_frame(r.frame_stage_ms, f);
    double sum = 0.0;
    for (const double ms : t) sum += ms;
    INFO("frame " << f);
    REQUIRE(sum <= r.frame_ms[f] + kFrameSlackMs);
  }
}

}  // namespace

TEST_CASE("frame stage times: each stage's frames add up to its total, each frame's stages to at most the frame",
          "[pipeline][frame-stages]") {
  PreparedCase p = prepared("building");
  p.spec.fade_out.enabled = true;
  p.spec.fade_out.max_volume = 1.0;
  p.spec.fade_out.lifetime_frames = 6;
  p.spec.debris.enabled = true;
  p.spec.debris.per_impact = 7;
  for (const ScheduleMode mode : {ScheduleMode::immediate, ScheduleMode::prefetch, ScheduleMode::amortized}) {
    INFO(schedule_mode_name(mode));
    const RunResult r = run(p, mode);
    REQUIRE_FALSE(r.hit.empty());
    require_conserved(r);
    // The event's stages are in its frames: the runtime fracture in a frame of the event, not before.
    const std::vector<double>& fracture = r.frame_stage_ms[static_cast<std::size_t>(Stage::runtime_fracture)];
    REQUIRE_FALSE(fracture.empty());
    const auto first = static_cast<int>(std::find_if(fracture.begin(), fracture.end(), [](double ms) { return ms > 0; }) -
                                        fracture.begin());
    REQUIRE(first >= r.latency.trigger_frame);
    REQUIRE(first <= r.latency.visible_frame);
    REQUIRE_FALSE(r.frame_stage_ms[static_cast<std::size_t>(Stage::physics)].empty());
    REQUIRE_FALSE(r.frame_stage_ms[static_cast<std::size_t>(Stage::debris)].empty());
  }
}
