#include "harness/pipeline/frame/frame_loop.h"

#include "algorithms/core/mesh.h"
#include "harness/pipeline/event/event_phases.h"
#include "harness/pipeline/frame/fade_out.h"
#include "harness/pipeline/frame/frame_recorder.h"
#include "harness/pipeline/frame/planted_slowdown.h"
#include "harness/pipeline/schedule/event_schedules.h"

#include <algorithm>
#include <chrono>
#include <memory>

namespace shatter {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void start_records(RunState& run, int frames) {
  RunResult& r = run.result;
  const auto n = static_cast<std::size_t>(frames);
  r.frame_ms.assign(n, 0.0);
  r.frame_cpu_ms.assign(n, 0.0);
  r.frame_work_ms.assign(n, 0.0);
  r.frame_bodies.assign(n, 0);
  r.frame_particles.assign(n, 0);
  if (run.spec.debris.enabled) {
    run.debris = std::make_unique<DebrisField>(run.spec.debris, run.spec.gravity, bounding_box(run.solid.mesh).min.z());
  } else {
    r.stages.skipped(Stage::debris, "the case has no debris (case key debris)");
  }
  if (run.spec.fade_out.enabled && !run.world) r.stages.skipped(Stage::colliders, "fade-out: no physics world (case needs)");
}

/// One event step, its wall time recorded per step and added to the frame's event work.
Result<double> timed_event_step(RunState& run, RuntimeEvent& event) {
  const auto start = std::chrono::steady_clock::now();
  Status s = run_event_step(run, event);
  const double ms = ms_since(start);
  RunResult& r = run.result;
  r.step_ms.push_back(ms);
  r.largest_step_ms = std::max(r.largest_step_ms, ms);
  r.frame_work_ms[static_cast<std::size_t>(run.frame)] += ms;
  if (!s) return s.error();
  return ms;
}

/// The physics step and the particles of the frame.
void step_world(RunState& run) {
  if (run.world && run.plan.physics) {
    StageTimer timer(run.result.frame_stages, Stage::physics);
    step_physics(*run.world);
  }
  if (run.debris && run.debris->size() > 0) {
    StageTimer timer(run.result.frame_stages, Stage::debris);
    run.debris->step(1.0 / 60.0);
  }
}

/// The frame's stage times: how much each stage's clock grew in it since `before` (frame_stage_ms).
void record_frame_stages(RunState& run, const StageTimes& before, int frames) {
  RunResult& r = run.result;
  for (std::size_t s = 0; s < kStageCount; ++s) {
    const double ms = round_to_clock_ms(r.frame_stages.wall[s] - before[s]);
    if (ms == 0.0) continue;
    std::vector<double>& column = r.frame_stage_ms[s];
    if (column.empty()) column.assign(static_cast<std::size_t>(frames), 0.0);
    column[static_cast<std::size_t>(run.frame)] = ms;
  }
}

void record_frame(RunState& run, double ms, double cpu_ms, bool event_frame) {
  RunResult& r = run.result;
  const auto f = static_cast<std::size_t>(run.frame);
  r.frame_ms[f] = ms;
  r.frame_cpu_ms[f] = cpu_ms;
  r.frame_bodies[f] = run.world ? run.world->body_count() : 0;
  r.frame_particles[f] = run.debris ? run.debris->size() : 0;
  r.bodies_peak = std::max(r.bodies_peak, r.frame_bodies[f]);
  r.particles_peak = std::max(r.particles_peak, r.frame_particles[f]);
  if (event_frame) {
    if (r.event_frames.empty()) r.event_ms = ms;
    r.event_frames.push_back(run.frame);
  }
}

}  // namespace

Status run_frames(RunState& run, std::vector<RuntimeEvent>& events, int frames) {
  start_records(run, frames);
  const EventStepper step = [&run](RuntimeEvent& e) { return timed_event_step(run, e); };
  EventQueue queue;
  std::size_t next = 0;
  for (run.frame = 0; run.frame < frames; ++run.frame) {
    instruction_marks::set_frame(run.frame);
    const StageTimes stages_before = run.result.frame_stages.wall;
    const double cpu_start = thread_cpu_ms();
    const auto start = std::chrono::steady_clock::now();
    bool event_frame = false;
    for (const RuntimeEvent& e : events) event_frame = event_frame || e.impact_frame == run.frame;
    while (next < events.size() && events[next].trigger_frame <= run.frame) queue.push_back(&events[next++]);
    const bool last_frame = run.frame == frames - 1;
    if (Status s = run_schedule(run.result.schedule, run.spec.schedule, queue, run.frame, last_frame, step); !s) return s;
    if (run.world) fade_out(run);
    step_world(run);
    const double ms = ms_since(start);
    const double cpu_ms = thread_cpu_ms() - cpu_start;
    record_frame(run, ms, cpu_ms, event_frame);
    record_frame_stages(run, stages_before, frames);
    if (run.options.recorder)
      if (Status s = run.options.recorder->record(run.world.get(), run.frame); !s) return s;
  }
  if (run.world && run.plan.physics) run.result.stages.ran(Stage::physics);
  return {};
}

}  // namespace shatter
