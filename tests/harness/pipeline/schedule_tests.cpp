// Scheduling of the runtime event (immediate, prefetch, amortized): the same outcome under every
// schedule, the amortized work bound, latency in frames, fade-out and debris (docs/pipeline.md section 6).

#include "harness/cases/case_library.h"
#include "harness/cases/case_loader.h"
#include "harness/pipeline/debris_field.h"
#include "harness/pipeline/destruction_run.h"
#include "tests/support/builtin_registries.h"

#include "tests/support/prepared_case.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace shatter;

using test::prepared;

RunResult run(const PreparedCase& p, ScheduleMode mode, int frames = 40, int threads = 1) {
  RunOptions o;
  o.threads = threads;
  o.partition_samples = 0;
  o.frames = frames;
  o.prefracture_fragments = 30;
  o.runtime_fragments = 10;
  o.schedule = mode;
  Result<RunResult> r = run_destruction(p, o, test::builtin_registries());
  INFO((r ? std::string() : r.error().message));
  REQUIRE(r);
  return std::move(*r);
}

bool same_fragments(const std::vector<Fragment>& a, const std::vector<Fragment>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].mesh.vertices != b[i].mesh.vertices || a[i].mesh.triangles != b[i].mesh.triangles ||
        a[i].mass.volume != b[i].mass.volume)
      return false;
  return true;
}

void require_same_outcome(const RunResult& a, const RunResult& b) {
  REQUIRE(same_fragments(a.fragments, b.fragments));
  REQUIRE(a.graph.bond_count() == b.graph.bond_count());
  REQUIRE(a.broken == b.broken);
  REQUIRE(a.hit == b.hit);
  REQUIRE(a.pieces.size() == b.pieces.size());
  for (std::size_t k = 0; k < a.pieces.size(); ++k) REQUIRE(same_fragments(a.pieces[k], b.pieces[k]));
  REQUIRE(a.falling_clusters == b.falling_clusters);
  REQUIRE(a.bodies == b.bodies);
}

}  // namespace

TEST_CASE("schedule: immediate, prefetch and amortized give the same fragments, bonds and falling clusters",
          "[pipeline][schedule]") {
  for (const char* name : {"building", "cantilever"}) {
    PreparedCase p = prepared(name);
    p.spec.schedule.work_budget_ms = 0.0;  // one step a frame: the most spread-out amortized run
    const RunResult immediate = run(p, ScheduleMode::immediate);
    const RunResult prefetch = run(p, ScheduleMode::prefetch);
    const RunResult amortized = run(p, ScheduleMode::amortized);
    INFO(name);
    REQUIRE(!immediate.hit.empty());
    require_same_outcome(immediate, prefetch);
    require_same_outcome(immediate, amortized);
    REQUIRE(immediate.step_ms.size() == amortized.step_ms.size());
    if (std::string(name) == "cantilever") REQUIRE(!immediate.falling_clusters.empty());
  }
}

TEST_CASE("threads: an event's fractures and colliders on worker threads give the same outcome as on one",
          "[pipeline][schedule][threads]") {
  // tower: several hit fragments (a fracture step takes one per thread); cantilever: falling clusters.
  for (const char* name : {"tower", "cantilever"}) {
    PreparedCase p = prepared(name);
    p.spec.schedule.work_budget_ms = 0.0;
    const RunResult one = run(p, ScheduleMode::immediate, 40, 1);
    INFO(name);
    REQUIRE(one.hit.size() >= (std::string(name) == "tower" ? 2U : 1U));
    for (const int threads : {2, 3}) {
      INFO("threads " << threads);
      const RunResult several = run(p, ScheduleMode::immediate, 40, threads);
      require_same_outcome(one, several);
      REQUIRE(several.frame_bodies == one.frame_bodies);
      // Amortized: the same outcome in fewer steps (a fracture step per `threads` hit fragments, a
      // colliders step per kColliderBatch pieces a thread).
      const RunResult amortized_one = run(p, ScheduleMode::amortized, 40, 1);
      const RunResult amortized = run(p, ScheduleMode::amortized, 40, threads);
      require_same_outcome(one, amortized);
      if (one.hit.size() > 1) REQUIRE(amortized.step_ms.size() < amortized_one.step_ms.size());
    }
  }
}

TEST_CASE("spawn cap: new bodies enter whole hit fragments at a time, at most the cap a frame, the rest later",
          "[pipeline][schedule][spawn]") {
  PreparedCase p = prepared("tower");
  const RunResult all = run(p, ScheduleMode::immediate);
  REQUIRE(all.hit.size() >= 2);
  REQUIRE(all.latency.frames == 1);
  for (const int cap : {1, 12, 25}) {
    INFO("cap " << cap);
    p.spec.schedule.max_new_bodies_per_frame = cap;
    for (const ScheduleMode mode : {ScheduleMode::immediate, ScheduleMode::amortized}) {
      const RunResult capped = run(p, mode);
      require_same_outcome(all, capped);
      // The frames the rule needs: hit fragments' pieces, then each falling cluster (one body), in
      // order, a frame taking items while they fit under the cap and always at least one.
      int frames = 1;
      int in_frame = 0;
      std::vector<int> items;
      for (const auto& pieces : capped.pieces) items.push_back(static_cast<int>(pieces.size()));
      for (std::size_t k = 0; k < capped.falling_clusters.size(); ++k) items.push_back(1);
      for (const int bodies : items) {
        if (in_frame > 0 && in_frame + bodies > cap) {
          ++frames;
          in_frame = 0;
        }
        in_frame += bodies;
      }
      if (mode == ScheduleMode::immediate) {
        REQUIRE(capped.latency.frames == frames);
        REQUIRE(capped.latency.visible_frame == capped.latency.impact_frame + frames - 1);
      } else {
        REQUIRE(capped.latency.frames >= frames);  // amortized adds the frames of its other steps
      }
      if (frames > 1) {
        // In the impact frame fewer bodies stand than when all enter at once.
        const auto impact = static_cast<std::size_t>(all.latency.visible_frame);
        if (mode == ScheduleMode::immediate) REQUIRE(capped.frame_bodies[impact] < all.frame_bodies[impact]);
      }
    }
  }
  p.spec.schedule.max_new_bodies_per_frame = 0;
  require_same_outcome(all, run(p, ScheduleMode::immediate));
}

TEST_CASE("schedule: amortized never spends more than its budget plus one step in a frame", "[pipeline][schedule]") {
  PreparedCase p = prepared("building");
  for (const double budget : {0.0, 0.3, 1.0}) {
    p.spec.schedule.work_budget_ms = budget;
    const RunResult r = run(p, ScheduleMode::amortized);
    REQUIRE(r.step_ms.size() > 1);
    for (const double w : r.frame_work_ms) REQUIRE(w <= budget + r.largest_step_ms);
    if (budget == 0.0) {
      // One step a frame: the event is visible in the frame of its last step.
      REQUIRE(r.latency.frames == static_cast<int>(r.step_ms.size()));
      REQUIRE(r.latency.after_impact == r.latency.frames - 1);
    }
  }
}

TEST_CASE("schedule: latency of immediate is one frame, of prefetch zero frames after the impact",
          "[pipeline][schedule]") {
  PreparedCase p = prepared("building");
  p.spec.schedule.prefetch_frames = 3;
  const int impact = p.spec.impacts.front().frame;
  const RunResult immediate = run(p, ScheduleMode::immediate);
  REQUIRE(immediate.latency.trigger_frame == impact);
  REQUIRE(immediate.latency.visible_frame == impact);
  REQUIRE(immediate.latency.frames == 1);
  REQUIRE(immediate.latency.after_impact == 0);
  REQUIRE(immediate.latency.ms >= 1000.0 / 60.0);

  const RunResult prefetch = run(p, ScheduleMode::prefetch);
  REQUIRE(prefetch.latency.trigger_frame == impact - 3);
  REQUIRE(prefetch.latency.visible_frame == impact);
  REQUIRE(prefetch.latency.after_impact == 0);
  REQUIRE(prefetch.latency.frames == 4);
  // The fracture ran in the trigger frame; nothing of the event ran in between.
  REQUIRE(prefetch.frame_work_ms[static_cast<std::size_t>(impact - 3)] > 0.0);
  for (int f = impact - 2; f < impact; ++f) REQUIRE(prefetch.frame_work_ms[static_cast<std::size_t>(f)] == 0.0);
  // Before the impact the pieces are not in the world.
  REQUIRE(prefetch.frame_bodies[static_cast<std::size_t>(impact - 1)] ==
          immediate.frame_bodies[static_cast<std::size_t>(impact - 1)]);
}

TEST_CASE("fade-out: small runtime pieces leave the world at the end of their lifetime", "[pipeline][fade-out]") {
  PreparedCase p = prepared("building");
  const RunResult plain = run(p, ScheduleMode::immediate);
  std::vector<double> volumes;
  for (const auto& list : plain.pieces)
    for (const Fragment& f : list) volumes.push_back(f.mass.volume);
  std::sort(volumes.begin(), volumes.end());
  const double threshold = volumes[volumes.size() / 2];  // about half the pieces fade
  const int expected = static_cast<int>(std::count_if(volumes.begin(), volumes.end(), [&](double v) { return v < threshold; }));
  REQUIRE(expected > 0);

  p.spec.fade_out.enabled = true;
  p.spec.fade_out.max_volume = threshold;
  p.spec.fade_out.lifetime_frames = 6;
  const RunResult faded = run(p, ScheduleMode::immediate);
  REQUIRE(plain.pieces.size() == faded.pieces.size());
  const auto v = static_cast<std::size_t>(faded.latency.visible_frame);
  const std::size_t gone = v + 6;  // removed before the physics step of visible + lifetime
  REQUIRE(faded.faded == expected);
  REQUIRE(faded.frame_bodies[v] == plain.frame_bodies[v]);
  REQUIRE(faded.frame_bodies[gone - 1] == plain.frame_bodies[gone - 1]);
  REQUIRE(faded.frame_bodies[gone] == plain.frame_bodies[gone] - expected);
  REQUIRE(faded.bodies == plain.bodies - expected);
}

TEST_CASE("debris: counts follow the cut area and the impact, particles die at the end of their life",
          "[pipeline][debris]") {
  PreparedCase p = prepared("building");
  const RunResult none = run(p, ScheduleMode::immediate);
  REQUIRE(none.particles_spawned == 0);
  REQUIRE(std::any_of(none.stages.skips().begin(), none.stages.skips().end(),
                      [](const StageSkip& s) { return s.stage == "debris"; }));

  p.spec.debris.enabled = true;
  p.spec.debris.per_area = 10.0;
  p.spec.debris.per_impact = 7;
  p.spec.debris.lifetime_frames = 5;
  const RunResult r = run(p, ScheduleMode::immediate);
  double area = 0.0;
  for (std::size_t k = 0; k < r.hit.size(); ++k)
    area += new_cut_area(r.fragments[static_cast<std::size_t>(r.hit[k])], r.pieces[k]);
  REQUIRE(area > 0.0);
  const int expected = static_cast<int>(std::lround(10.0 * area)) + 7;
  REQUIRE(r.particles_spawned == expected);
  const auto v = static_cast<std::size_t>(r.latency.visible_frame);
  REQUIRE(r.frame_particles[v - 1] == 0);
  REQUIRE(r.frame_particles[v] == expected);
  REQUIRE(r.frame_particles[v + 3] == expected);  // lived 4 frames
  REQUIRE(r.frame_particles[v + 4] == 0);         // the 5th frame was its last
  REQUIRE(r.frame_stages.wall[static_cast<std::size_t>(Stage::debris)] > 0.0);
}

TEST_CASE("debris: particles fall to the ground and stay on it", "[pipeline][debris]") {
  DebrisSpec spec;
  spec.enabled = true;
  spec.speed = 5.0;
  spec.lifetime_frames = 1000;
  DebrisField field(spec, Vec3(0, 0, -9.81), 0.0);
  REQUIRE(field.count_for(0.25) == 0);
  REQUIRE(field.spawn(20, {Vec3(0, 0, 1)}, 3) == 20);
  for (int i = 0; i < 999; ++i) field.step(1.0 / 60.0);
  REQUIRE(field.size() == 20);
  field.step(1.0 / 60.0);
  REQUIRE(field.size() == 0);
}

TEST_CASE("schedule: bad schedule, fade-out and debris keys are errors naming the key", "[pipeline][schedule]") {
  const std::string head = R"({"mesh": {"box": {"size": [1, 1, 1]}}, )";
  struct Bad {
    std::string body;
    std::string key;
  };
  const Bad cases[] = {
      {R"("schedule": {"mode": "later"}})", "schedule.mode"},
      {R"("schedule": {"work_budget_ms": -1}})", "schedule.work_budget_ms"},
      {R"("schedule": {"prefetch_frames": -2}})", "schedule.prefetch_frames"},
      {R"("schedule": {"max_new_bodies_per_frame": -1}})", "schedule.max_new_bodies_per_frame"},
      {R"("schedule": {"max_new_bodies_per_frame": 2.5}})", "schedule.max_new_bodies_per_frame"},
      {R"("schedule": {"mode": "prefetch", "frames": 2}})", "frames"},
      {R"("fade_out": {"volume": -0.1}})", "fade_out.volume"},
      {R"("fade_out": {"volume": 0.1, "lifetime_frames": 0}})", "fade_out.lifetime_frames"},
      {R"("debris": {"per_area": -1}})", "debris.per_area"},
      {R"("debris": {"per_impact": -1}})", "debris.per_impact"},
      {R"("debris": {"speed": -1}})", "debris.speed"},
  };
  for (const Bad& b : cases) {
    const Result<Case> c = parse_case(head + b.body, "x.json");
    INFO(b.body);
    REQUIRE_FALSE(c);
    INFO(c.error().message);
    REQUIRE(c.error().message.find(b.key) != std::string::npos);
  }
  const Result<Case> good =
      parse_case(head + R"("schedule": {"mode": "amortized", "work_budget_ms": 2, "max_new_bodies_per_frame": 40},
                 "fade_out": {"volume": 0.01},
                 "debris": {"per_impact": 5}})",
                 "x.json");
  REQUIRE(good);
  REQUIRE(good->schedule.mode == ScheduleMode::amortized);
  REQUIRE(good->schedule.max_new_bodies_per_frame == 40);
  REQUIRE(good->fade_out.enabled);
  REQUIRE(good->debris.per_impact == 5);
}
