#include "harness/grid/run_sample.h"

#include "harness/results/run_figures.h"

#include <algorithm>
#include <cstdint>

namespace shatter {
namespace {

double largest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

}  // namespace

FigureRecord run_record(const RunResult& run, const ExtraFigures& extra) {
  FigureRecord r = run_figure_defaults();
  int pieces = 0;
  for (const auto& p : run.pieces) pieces += static_cast<int>(p.size());
  r.set("cache_hit", run.cache_hit ? 1.0 : 0.0);
  r.set("fragments", static_cast<double>(run.fragments.size()));
  r.set("hit", static_cast<double>(run.hit.size()));
  r.set("pieces", pieces);
  r.set("broken_bonds", static_cast<double>(std::count(run.broken.begin(), run.broken.end(), std::uint8_t{1})));
  r.set("falling_clusters", static_cast<double>(run.falling_clusters.size()));
  r.set("bodies", run.bodies);
  r.set("solver.solves", run.solver.solves);
  r.set("solver.iterations", run.solver.iterations);
  r.set("solver.converged", run.solver.converged ? 1.0 : 0.0);
  r.set("solver.residual", run.solver.residual);
  r.set("solver.unknowns", run.solver.unknowns);
  r.set("latency_ms", run.latency.ms);
  r.set("latency_frames", run.latency.frames);
  r.set("latency_after_impact_frames", run.latency.after_impact);
  r.set("trigger_frame", run.latency.visible_frame >= 0 ? run.latency.trigger_frame : -1);
  r.set("visible_frame", run.latency.visible_frame);
  r.set("event_steps", static_cast<double>(run.step_ms.size()));
  r.set("largest_step_ms", run.largest_step_ms);
  r.set("worst_work_ms", largest(run.frame_work_ms));
  r.set("bodies_peak", run.bodies_peak);
  r.set("faded", run.faded);
  r.set("particles_spawned", run.particles_spawned);
  r.set("particles_peak", run.particles_peak);
  if (extra) extra(run, r);
  return r;
}

GridSample run_sample(const RunResult& run, const ExtraFigures& extra) {
  GridSample s;
  s.seed = run.prefracture_seed;
  s.frame_ms = run.frame_ms;
  s.event_ms = run.event_ms;
  s.event_frame = run.event_frames.empty() ? -1 : run.event_frames.front();
  s.worst_frame_ms = largest(run.frame_ms);
  s.stages_ms = run.frame_stages.wall;
  s.frame_stages_ms = run.frame_stage_ms;
  s.setup_ms = run.setup.wall;
  s.stages_cpu_ms = run.frame_stages.cpu;
  s.worst_frame_cpu_ms = largest(run.frame_cpu_ms);
  s.figures = run_record(run, extra);
  return s;
}

void add_run_accuracy(CellAccuracy& e, const RunResult& run, bool first) {
  const FractureMetrics& p = run.prefracture_error;
  const RuntimeFractureError& r = run.runtime_error;
  e.prefracture_volume_error = std::max(e.prefracture_volume_error, p.volume_error);
  e.prefracture_partition_error = std::max(e.prefracture_partition_error, p.partition_error);
  e.prefracture_all_closed = e.prefracture_all_closed && p.all_closed;
  e.prefracture_min_fragment_volume =
      first ? p.min_fragment_volume : std::min(e.prefracture_min_fragment_volume, p.min_fragment_volume);
  e.runtime_volume_error = std::max(e.runtime_volume_error, r.volume_error);
  e.runtime_partition_error = std::max(e.runtime_partition_error, r.partition_error);
  e.runtime_all_closed = e.runtime_all_closed && r.all_closed;
  if (r.pieces > 0)
    e.runtime_min_fragment_volume = e.runtime_min_fragment_volume == 0.0
                                        ? r.min_fragment_volume
                                        : std::min(e.runtime_min_fragment_volume, r.min_fragment_volume);
  e.solver_converged = e.solver_converged && run.solver.converged;
  e.solver_residual = std::max(e.solver_residual, run.solver.residual);
}

}  // namespace shatter
