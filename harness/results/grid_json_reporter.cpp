#include "harness/results/grid_json_reporter.h"

#include "harness/results/results_json_text.h"
#include "harness/results/run_figures.h"
#include "harness/results/worst_frame.h"

#include <fmt/core.h>

#include <cstdint>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

Json stages_json(const StageTimes& times) {
  Json j = Json::object();
  for (const Stage s : kAllStages) j[std::string(stage_name(s))] = times[static_cast<std::size_t>(s)];
  return j;
}

/// One array per stage that took time in some frame, in data-flow order; a frame without time in the
/// stage is written 0 (an integer: the arrays are mostly zeros outside the event's frames).
Json frame_stages_json(const FrameStageTimes& times) {
  Json j = Json::object();
  for (const Stage s : kAllStages) {
    const std::vector<double>& column = times[static_cast<std::size_t>(s)];
    if (column.empty()) continue;
    Json values = Json::array();
    for (const double ms : column) values.push_back(ms == 0.0 ? Json(0) : Json(ms));
    j[std::string(stage_name(s))] = std::move(values);
  }
  return j;
}

/// The stages of `frame` that frame_stages_json writes, each with its time in that frame.
Json frame_column_json(const FrameStageTimes& times, const StageTimes& frame) {
  Json j = Json::object();
  for (const Stage s : kAllStages)
    if (!times[static_cast<std::size_t>(s)].empty())
      j[std::string(stage_name(s))] = frame[static_cast<std::size_t>(s)];
  return j;
}

Json statistics_json(const SampleStatistics& s) {
  return {{"mean", s.mean}, {"median", s.median}, {"p95", s.p95}, {"p99", s.p99}, {"max", s.max}, {"min", s.min}};
}

Json accuracy_json(const CellAccuracy& e) {
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

Json figure_value(const Figure& f) {
  switch (f.spec.kind) {
    case FigureKind::integer: return static_cast<std::int64_t>(f.value);
    case FigureKind::flag: return f.value != 0.0;
    case FigureKind::number: return f.value;
  }
  return f.value;
}

Json sample_json(const GridSample& s) {
  Json j = {{"seed", s.seed}, {"frame_ms", s.frame_ms}};
  if (s.frame_stages_ms) j["frame_stages_ms"] = frame_stages_json(*s.frame_stages_ms);
  j.update(Json{{"event_ms", s.event_ms}, {"event_frame", s.event_frame}, {"worst_frame_ms", s.worst_frame_ms}});
  if (const std::optional<WorstFrame> w = sample_worst_frame(s, 0))
    j["worst_frame_stages_ms"] = frame_column_json(*s.frame_stages_ms, w->stages);
  j.update(Json{{"stages_ms", stages_json(s.stages_ms)},
                {"setup_ms", stages_json(s.setup_ms)},
                {"cpu", {{"worst_frame_ms", s.worst_frame_cpu_ms}, {"stages_ms", stages_json(s.stages_cpu_ms)}}},
                {"calibration_ms", s.calibration_ms}});
  for (const Figure& f : s.figures.figures()) put_figure(j, f);
  if (s.instructions) j["instructions"] = instructions_json(*s.instructions);
  return j;
}

/// The `recorded_frames` block: the sidecar's name (in the JSON's folder), size and layout, and what
/// each of its recordings holds, in the sidecar's order.
Json recorded_frames_json(const GridResult& grid) {
  Json recordings = Json::array();
  for (const GridCell& c : grid.cells) {
    if (!c.recording) continue;
    const RecordedFrames& r = *c.recording;
    recordings.push_back({{"prefracture", r.prefracture},
                          {"runtime", r.runtime},
                          {"repetition", r.repetition},
                          {"seed", r.seed},
                          {"frames", r.frames},
                          {"bodies", r.bodies.size()},
                          {"meshes", r.meshes.size()}});
  }
  return {{"path", grid.recorded_frames_file},
          {"bytes", grid.recorded_frames_bytes},
          {"layout", fmt::format("SBFRAMES version {}, docs/results.md (Recorded frames)", kRecordedFramesVersion)},
          {"recordings", recordings}};
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

}  // namespace

void put_figure(nlohmann::ordered_json& object, const Figure& figure) {
  Json* at = &object;
  std::string_view name = figure.spec.name;
  for (std::size_t dot = name.find('.'); dot != std::string_view::npos; dot = name.find('.')) {
    at = &(*at)[std::string(name.substr(0, dot))];
    name = name.substr(dot + 1);
  }
  (*at)[std::string(name)] = figure_value(figure);
}

nlohmann::ordered_json grid_cell_to_json(const GridCell& c) {
  if (!c.failed.empty()) return failed_cell_json(c);
  Json samples = Json::array();
  for (const GridSample& s : c.samples) samples.push_back(sample_json(s));
  Json skipped = Json::array();
  for (const StageSkip& s : c.stages_skipped) skipped.push_back({{"stage", s.stage}, {"reason", s.reason}});
  Json j = {{"prefracture", c.prefracture},
            {"runtime", c.runtime},
            {"prefracturer", c.prefracturer},
            {"fracturer", c.fracturer},
            {"stress", c.stress},
            {"worst_frame_ms", c.worst_frame_ms}};
  if (const std::optional<WorstFrame> w = cell_worst_frame(c)) {
    j["worst_frame_repetition"] = w->repetition;
    j["worst_frame_stages_ms"] =
        frame_column_json(*c.samples[static_cast<std::size_t>(w->repetition)].frame_stages_ms, w->stages);
  }
  j.update(Json{{"frame_ms", statistics_json(c.frame_ms)},
                {"event_ms", c.event_ms},
                {"stages_ms", stages_json(c.stages_ms)},
                {"setup_ms", stages_json(c.setup_ms)},
                {"error", accuracy_json(c.accuracy)},
                {"within_budget", c.within_budget},
                {"stages_run", c.stages_run},
                {"stages_skipped", skipped},
                {"schedule", c.schedule}});
  bool verdict_written = false;
  for (const Figure& f : c.summaries.figures()) {
    if (!verdict_written && f.spec.cell_order >= kLatencyVerdictCellOrder) {
      j["within_latency_budget"] = c.within_latency_budget;
      verdict_written = true;
    }
    put_figure(j, f);
  }
  if (!verdict_written) j["within_latency_budget"] = c.within_latency_budget;
  j["samples"] = samples;
  return j;
}

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
                                    const RunContext& context, const nlohmann::ordered_json& input_block) {
  Json cells = Json::array();
  for (const GridCell& cell : grid.cells) cells.push_back(grid_cell_to_json(cell));
  Json out = {{"schema_version", kGridSchemaVersion},
              {"metric", grid.metric},
              {"context", to_json(context)},
              {"case", case_block}};
  if (!input_block.is_null()) out["input"] = input_block;
  out.update(Json{{"budget_ms", grid.budget_ms},
              {"latency_budget_ms", grid.latency_budget_ms},
              {"repetitions", grid.repetitions},
              {"frames", grid.frames},
              {"no_skip", grid.no_skip},
              {"same_seed", grid.same_seed},
              {"threads", grid.threads}});
  if (grid.shard_count > 1) out["shard"] = {{"index", grid.shard_index}, {"count", grid.shard_count}};
  if (grid.cell_timeout_s > 0.0) out["cell_timeout_s"] = grid.cell_timeout_s;
  out["passed"] = grid.passed();
  out["wall_s"] = grid.wall_s;
  if (!grid.recorded_frames_file.empty()) out["recorded_frames"] = recorded_frames_json(grid);
  out["cells"] = cells;
  return out;
}

std::string JsonGridReporter::render(const GridReport& r) const {
  return results_json_text(grid_to_json(r.grid, r.case_block, r.context, r.input_block)) + "\n";
}

}  // namespace shatter
