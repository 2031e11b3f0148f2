#include "harness/results/grid_report.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>

#include "harness/results/sample_statistics.h"

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

Json stages_json(const StageTimes& times) {
  Json j = Json::object();
  for (const Stage s : kAllStages) j[std::string(stage_name(s))] = times[static_cast<std::size_t>(s)];
  return j;
}

Json statistics_json(const SampleStatistics& s) {
  return {{"mean", s.mean}, {"median", s.median}, {"p95", s.p95}, {"p99", s.p99}, {"max", s.max}, {"min", s.min}};
}

Json solver_json(const SolverReport& r) {
  return {{"solves", r.solves},
          {"iterations", r.iterations},
          {"converged", r.converged},
          {"residual", r.residual},
          {"unknowns", r.unknowns}};
}

Json error_json(const CellError& e) {
  return {{"prefracture",
           {{"volume_error", e.prefracture_volume_error},
            {"partition_error", e.prefracture_partition_error},
            {"all_closed", e.prefracture_all_closed},
            {"min_fragment_volume", e.prefracture_min_fragment_volume}}},
          {"runtime",
           {{"volume_error", e.runtime_volume_error},
            {"partition_error", e.runtime_partition_error},
            {"all_closed", e.runtime_all_closed},
            {"min_fragment_volume", e.runtime_min_fragment_volume}}},
          {"stress", {{"converged", e.solver_converged}, {"residual", e.solver_residual}}}};
}

Json instructions_json(const InstructionCounts& c) {
  return {{"stages", stages_json(c.stages)},
          {"setup", stages_json(c.setup)},
          {"frames", c.frames},
          {"event", c.event},
          {"worst_frame", c.worst_frame}};
}

Json sample_json(const GridSample& s) {
  Json j = {{"seed", s.seed},
          {"frame_ms", s.frame_ms},
          {"event_ms", s.event_ms},
          {"event_frame", s.event_frame},
          {"worst_frame_ms", s.worst_frame_ms},
          {"stages_ms", stages_json(s.stages_ms)},
          {"setup_ms", stages_json(s.setup_ms)},
          {"cpu", {{"worst_frame_ms", s.worst_frame_cpu_ms}, {"stages_ms", stages_json(s.stages_cpu_ms)}}},
          {"calibration_ms", s.calibration_ms},
          {"cache_hit", s.cache_hit},
          {"fragments", s.fragments},
          {"hit", s.hit},
          {"pieces", s.pieces},
          {"broken_bonds", s.broken_bonds},
          {"falling_clusters", s.falling_clusters},
          {"bodies", s.bodies},
          {"solver", solver_json(s.solver)},
          {"latency_ms", s.latency_ms},
          {"latency_frames", s.latency_frames},
          {"latency_after_impact_frames", s.latency_after_impact_frames},
          {"trigger_frame", s.trigger_frame},
          {"visible_frame", s.visible_frame},
          {"event_steps", s.event_steps},
          {"largest_step_ms", s.largest_step_ms},
          {"worst_work_ms", s.worst_work_ms},
          {"bodies_peak", s.bodies_peak},
          {"faded", s.faded},
          {"particles_spawned", s.particles_spawned},
          {"particles_peak", s.particles_peak}};
  if (s.instructions) j["instructions"] = instructions_json(*s.instructions);
  return j;
}

/// A failed cell keeps its settings and the reason; it has no figures.
Json failed_cell_json(const GridCell& c) {
  return {{"prefracture", c.prefracture},
          {"runtime", c.runtime},
          {"prefracturer", c.prefracturer},
          {"fracturer", c.fracturer},
          {"stress", c.stress},
          {"schedule", c.schedule},
          {"failed", c.failed},
          {"within_budget", false},
          {"within_latency_budget", false},
          {"samples", Json::array()}};
}

Json cell_json(const GridCell& c) {
  if (!c.failed.empty()) return failed_cell_json(c);
  Json samples = Json::array();
  for (const GridSample& s : c.samples) samples.push_back(sample_json(s));
  Json skipped = Json::array();
  for (const StageSkip& s : c.stages_skipped) skipped.push_back({{"stage", s.stage}, {"reason", s.reason}});
  return {{"prefracture", c.prefracture},
          {"runtime", c.runtime},
          {"prefracturer", c.prefracturer},
          {"fracturer", c.fracturer},
          {"stress", c.stress},
          {"worst_frame_ms", c.worst_frame_ms},
          {"frame_ms", statistics_json(c.frame_ms)},
          {"event_ms", c.event_ms},
          {"stages_ms", stages_json(c.stages_ms)},
          {"setup_ms", stages_json(c.setup_ms)},
          {"error", error_json(c.error)},
          {"within_budget", c.within_budget},
          {"stages_run", c.stages_run},
          {"stages_skipped", skipped},
          {"schedule", c.schedule},
          {"latency_ms", c.latency_ms},
          {"latency_frames", c.latency_frames},
          {"within_latency_budget", c.within_latency_budget},
          {"largest_step_ms", c.largest_step_ms},
          {"bodies", c.bodies},
          {"bodies_peak", c.bodies_peak},
          {"particles_peak", c.particles_peak},
          {"samples", samples}};
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

}  // namespace

nlohmann::ordered_json grid_cell_to_json(const GridCell& cell) { return cell_json(cell); }

nlohmann::ordered_json case_to_json(const Case& c) {
  Json impacts = Json::array();
  for (const ImpactEvent& e : c.impacts)
    impacts.push_back({{"frame", e.frame},
                       {"point", {e.impact.point.x(), e.impact.point.y(), e.impact.point.z()}},
                       {"direction", {e.impact.direction.x(), e.impact.direction.y(), e.impact.direction.z()}},
                       {"impulse", e.impact.impulse},
                       {"radius", e.impact.radius}});
  return {{"name", c.name},
          {"description", c.description},
          {"source", c.source.string()},
          {"gravity", {c.gravity.x(), c.gravity.y(), c.gravity.z()}},
          {"anchors", c.anchors.size()},
          {"impacts", impacts},
          {"frames", c.frames},
          {"budget_ms", c.budget_ms},
          {"needs", c.needs.names()}};
}

nlohmann::ordered_json grid_to_json(const GridResult& grid, const nlohmann::ordered_json& case_block,
                                    const RunContext& context) {
  Json cells = Json::array();
  for (const GridCell& cell : grid.cells) cells.push_back(cell_json(cell));
  Json out = {{"schema_version", kGridSchemaVersion},
              {"metric", grid.metric},
              {"context", to_json(context)},
              {"case", case_block},
              {"budget_ms", grid.budget_ms},
              {"latency_budget_ms", grid.latency_budget_ms},
              {"repetitions", grid.repetitions},
              {"frames", grid.frames},
              {"no_skip", grid.no_skip},
              {"same_seed", grid.same_seed}};
  if (grid.shard_count > 1) out["shard"] = {{"index", grid.shard_index}, {"count", grid.shard_count}};
  if (grid.cell_timeout_s > 0.0) out["cell_timeout_s"] = grid.cell_timeout_s;
  out["passed"] = grid.passed();
  out["wall_s"] = grid.wall_s;
  out["cells"] = cells;
  return out;
}

std::string grid_to_csv(const GridResult& grid) {
  std::string out = "prefracture,runtime,prefracturer,fracturer,stress,worst_frame_ms,mean_ms,median_ms,p95_ms,p99_ms,"
                    "max_ms,min_ms,event_ms";
  for (const Stage s : kAllStages) out += fmt::format(",{}_ms", stage_name(s));
  out +=
      ",prefracture_volume_error,runtime_volume_error,within_budget,schedule,latency_ms,latency_frames,bodies,"
      "bodies_peak,particles_peak,within_latency_budget,failed\n";
  for (const GridCell& c : grid.cells) {
    if (!c.failed.empty()) {  // settings, the verdicts and the reason; no figures
      out += fmt::format("{},{},{},{},{},,,,,,,,", c.prefracture, c.runtime, c.prefracturer, c.fracturer, c.stress);
      for (std::size_t k = 0; k < kAllStages.size(); ++k) out += ",";
      out += fmt::format(",,,false,{},,,,,,false,{}\n", c.schedule, csv_field(c.failed));
      continue;
    }
    out += fmt::format("{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}", c.prefracture,
                       c.runtime, c.prefracturer, c.fracturer, c.stress, c.worst_frame_ms, c.frame_ms.mean,
                       c.frame_ms.median, c.frame_ms.p95, c.frame_ms.p99, c.frame_ms.max, c.frame_ms.min, c.event_ms);
    for (const Stage s : kAllStages) out += fmt::format(",{:.6f}", c.stages_ms[static_cast<std::size_t>(s)]);
    out += fmt::format(",{:.3e},{:.3e},{},{},{:.6f},{:g},{:g},{:g},{:g},{},\n", c.error.prefracture_volume_error,
                       c.error.runtime_volume_error, c.within_budget ? "true" : "false", c.schedule, c.latency_ms,
                       c.latency_frames, c.bodies, c.bodies_peak, c.particles_peak,
                       c.within_latency_budget ? "true" : "false");
  }
  return out;
}

namespace {

/// A Markdown table with pre-fracture counts as rows and runtime counts as columns (in the order the
/// cells come), each cell's text from `text` (" |"-terminated by the caller's format).
std::string cell_table(const GridResult& grid, const std::function<std::string(const GridCell&)>& text) {
  std::vector<int> rows, cols;
  std::map<std::pair<int, int>, const GridCell*> at;
  for (const GridCell& c : grid.cells) {
    if (std::find(rows.begin(), rows.end(), c.prefracture) == rows.end()) rows.push_back(c.prefracture);
    if (std::find(cols.begin(), cols.end(), c.runtime) == cols.end()) cols.push_back(c.runtime);
    at[{c.prefracture, c.runtime}] = &c;
  }
  std::string out = "| pre-fracture \\ runtime |";
  for (const int c : cols) out += fmt::format(" {} |", c);
  out += "\n|---:|";
  for (std::size_t i = 0; i < cols.size(); ++i) out += "---:|";
  out += "\n";
  for (const int r : rows) {
    out += fmt::format("| {} |", r);
    for (const int c : cols) {
      const auto it = at.find({r, c});
      out += it == at.end() ? std::string(" |") : fmt::format(" {} |", text(*it->second));
    }
    out += "\n";
  }
  return out;
}

}  // namespace

std::string grid_to_markdown(const GridResult& grid, const std::string& case_name) {
  std::string out;
  if (!grid.cells.empty()) {
    const GridCell& first = grid.cells.front();
    out += fmt::format("Case `{}`: pre-fracture {}, runtime {}, stress {}; worst frame in ms (median over {} "
                       "repetitions of each one's slowest of {} frames); budget {} ms; schedule {}\n\n",
                       case_name, first.prefracturer, first.fracturer, first.stress, grid.repetitions, grid.frames,
                       grid.budget_ms, first.schedule);
  }
  out += cell_table(grid, [](const GridCell& c) {
    if (!c.failed.empty()) return fmt::format("**{} !**", c.failed);
    return c.within_budget ? fmt::format("{:.2f}", c.worst_frame_ms) : fmt::format("**{:.2f} !**", c.worst_frame_ms);
  });
  if (!grid.cells.empty()) {
    out += fmt::format("\nLatency, trigger to visible at 60 Hz: ms (frames), budget {} ms; bodies at the end / peak; "
                       "particles peak (medians over repetitions)\n\n",
                       grid.latency_budget_ms);
    out += cell_table(grid, [](const GridCell& g) {
      if (!g.failed.empty()) return std::string("**failed !**");
      return fmt::format("{}{:.1f} ({:g}){} · {:g}/{:g} · {:g}", g.within_latency_budget ? "" : "**", g.latency_ms,
                         g.latency_frames, g.within_latency_budget ? "" : " !**", g.bodies, g.bodies_peak,
                         g.particles_peak);
    });
  }
  int over = 0, late = 0;
  std::vector<std::string> failed;
  for (const GridCell& c : grid.cells) {
    if (!c.failed.empty()) {
      failed.push_back(fmt::format("cell {} x {}: {}", c.prefracture, c.runtime, c.failed));
      continue;
    }
    over += c.within_budget ? 0 : 1;
    late += c.within_latency_budget ? 0 : 1;
  }
  if (!failed.empty())
    out += fmt::format("\n{} of {} cells failed (marked !): {}.\n", failed.size(), grid.cells.size(),
                       fmt::join(failed, "; "));
  if (late > 0)
    out += fmt::format("\n{} of {} cells over the {} ms latency budget (marked !).\n", late, grid.cells.size(),
                       grid.latency_budget_ms);
  if (over == 0 && failed.empty()) {
    out += fmt::format("\nAll {} cells within the {} ms budget ({:.1f} s).\n", grid.cells.size(), grid.budget_ms,
                       grid.wall_s);
  } else if (over > 0) {
    out += fmt::format("\n{} of {} cells over the {} ms budget (marked !).\n", over, grid.cells.size(), grid.budget_ms);
  }
  return out;
}

std::string grid_instructions_markdown(const GridResult& grid, const std::string& case_name) {
  std::string out = fmt::format("Case `{}`: retired instructions of the largest frame, millions (median over {} "
                                "repetitions of {} frames; counted under callgrind)\n\n",
                                case_name, grid.repetitions, grid.frames);
  out += cell_table(grid, [](const GridCell& c) {
    if (!c.failed.empty()) return fmt::format("**{} !**", c.failed);
    std::vector<double> v;
    for (const GridSample& s : c.samples)
      if (s.instructions) v.push_back(s.instructions->worst_frame);
    return fmt::format("{:.3f}", median_of(v) / 1e6);
  });
  return out;
}

}  // namespace shatter
