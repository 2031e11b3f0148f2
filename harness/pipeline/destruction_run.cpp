#include "harness/pipeline/destruction_run.h"

#include "harness/cases/case_mesh.h"
#include "harness/pipeline/event/runtime_event.h"
#include "harness/pipeline/frame/frame_loop.h"
#include "harness/pipeline/run_state.h"
#include "harness/pipeline/schedule/event_latency.h"
#include "harness/pipeline/setup/run_setup.h"

#include <algorithm>
#include <utility>

namespace shatter {
namespace {

/// Error figures of the runtime fracture over every hit fragment and its pieces (after the frames: a
/// measurement, not a stage).
RuntimeFractureError measure_runtime_error(const RunState& run) {
  const RunResult& r = run.result;
  RuntimeFractureError e;
  FractureMetricsOptions options;
  options.partition_samples = run.options.partition_samples;
  for (std::size_t k = 0; k < r.hit.size(); ++k) {
    const Fragment& parent = r.fragments[static_cast<std::size_t>(r.hit[k])];
    const FractureMetrics m = fracture_metrics(parent.mesh, parent.mass, r.pieces[k], run.runtime_fragments, options);
    e.volume_error = std::max(e.volume_error, m.volume_error);
    e.partition_error = std::max(e.partition_error, m.partition_error);
    e.all_closed = e.all_closed && m.all_closed;
    if (e.pieces == 0 || m.min_fragment_volume < e.min_fragment_volume) e.min_fragment_volume = m.min_fragment_volume;
    e.pieces += static_cast<int>(r.pieces[k].size());
    ++e.hit_count;
  }
  return e;
}

/// Every event's latency, in landing order, and the slowest.
void record_latencies(RunResult& r, const std::vector<RuntimeEvent>& events) {
  for (const RuntimeEvent& e : events) {
    const EventLatency l = event_latency(e, r.frame_ms);
    r.latencies.push_back(l);
    if (r.latency.visible_frame < 0 || l.ms > r.latency.ms) r.latency = l;
  }
}

}  // namespace

Result<PreparedCase> prepare_case(Case c) {
  Result<Solid> solid = build_case_solid(c);
  if (!solid) return solid.error();
  return PreparedCase{std::move(c), std::move(*solid)};
}

Result<RunResult> run_destruction(const PreparedCase& prepared, const RunOptions& options) {
  RunState run(prepared, options);
  const Case& c = run.spec;
  run.plan = plan_for(c.needs);
  instruction_marks::set_frame(-1);
  if (Status s = run_setup(run); !s) return s.error();
  run.result.runtime_seed = c.prefracture.seed + options.repetition;
  run.result.schedule = options.schedule.value_or(c.schedule.mode);

  const int frames = options.frames > 0 ? options.frames : c.frames;
  std::vector<RuntimeEvent> events =
      events_in_landing_order(c.impacts, frames, run.result.schedule, c.schedule.prefetch_frames);
  if (Status s = run_frames(run, events, frames); !s) return s.error();
  record_latencies(run.result, events);
  run.result.runtime_error = measure_runtime_error(run);
  if (run.world) run.result.bodies = run.world->body_count();
  return std::move(run.result);
}

}  // namespace shatter
