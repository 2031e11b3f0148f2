#include "harness/results/grid_csv_reporter.h"

#include "harness/results/run_figures.h"

#include <fmt/core.h>

#include <algorithm>

namespace shatter {
namespace {

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

/// The figure columns: every summarised run figure with a column, then any other summary a cell
/// holds with one, ordered by csv_order (ties in that order).
std::vector<FigureSpec> figure_columns(const GridResult& grid) {
  std::vector<FigureSpec> columns;
  const auto add = [&](const FigureSpec& spec) {
    if (spec.summary == CellSummary::none || spec.csv_order == kNoCsvColumn) return;
    if (std::none_of(columns.begin(), columns.end(), [&](const FigureSpec& c) { return c.name == spec.name; }))
      columns.push_back(spec);
  };
  for (const FigureSpec& spec : run_figure_specs()) add(spec);
  for (const GridCell& c : grid.cells)
    for (const Figure& f : c.summaries.figures()) add(f.spec);
  std::stable_sort(columns.begin(), columns.end(),
                   [](const FigureSpec& a, const FigureSpec& b) { return a.csv_order < b.csv_order; });
  return columns;
}

/// The figure columns of `cell`, with `within_latency_budget` (`verdict`) at its place; empty fields
/// for a figure the cell does not hold (`texts` false: every field empty but the verdict).
std::string figure_fields(const std::vector<FigureSpec>& columns, const GridCell& cell, const std::string& verdict,
                          bool texts) {
  std::string out;
  bool verdict_written = false;
  for (const FigureSpec& spec : columns) {
    if (!verdict_written && spec.csv_order >= kLatencyVerdictCsvOrder) {
      out += "," + verdict;
      verdict_written = true;
    }
    const Figure* f = texts ? cell.summaries.find(spec.name) : nullptr;
    out += "," + (f != nullptr ? figure_text(*f) : std::string());
  }
  if (!verdict_written) out += "," + verdict;
  return out;
}

}  // namespace

std::string grid_to_csv(const GridResult& grid) {
  const std::vector<FigureSpec> columns = figure_columns(grid);
  std::string out = "prefracture,runtime,prefracturer,fracturer,stress,worst_frame_ms,mean_ms,median_ms,p95_ms,p99_ms,"
                    "max_ms,min_ms,event_ms";
  for (const Stage s : kAllStages) out += fmt::format(",{}_ms", stage_name(s));
  out += ",prefracture_volume_error,runtime_volume_error,within_budget,schedule";
  bool verdict_written = false;
  for (const FigureSpec& spec : columns) {
    if (!verdict_written && spec.csv_order >= kLatencyVerdictCsvOrder) {
      out += ",within_latency_budget";
      verdict_written = true;
    }
    out += "," + csv_field(spec.name);
  }
  if (!verdict_written) out += ",within_latency_budget";
  out += ",failed\n";
  for (const GridCell& c : grid.cells) {
    if (!c.failed.empty()) {  // settings, the verdicts and the reason; no figures
      out += fmt::format("{},{},{},{},{},,,,,,,,", c.prefracture, c.runtime, c.prefracturer, c.fracturer, c.stress);
      for (std::size_t k = 0; k < kAllStages.size(); ++k) out += ",";
      out += fmt::format(",,,false,{}", c.schedule);
      out += figure_fields(columns, c, "false", false);
      out += "," + csv_field(c.failed) + "\n";
      continue;
    }
    out += fmt::format("{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}", c.prefracture,
                       c.runtime, c.prefracturer, c.fracturer, c.stress, c.worst_frame_ms, c.frame_ms.mean,
                       c.frame_ms.median, c.frame_ms.p95, c.frame_ms.p99, c.frame_ms.max, c.frame_ms.min, c.event_ms);
    for (const Stage s : kAllStages) out += fmt::format(",{:.6f}", c.stages_ms[static_cast<std::size_t>(s)]);
    out += fmt::format(",{:.3e},{:.3e},{},{}", c.accuracy.prefracture_volume_error, c.accuracy.runtime_volume_error,
                       c.within_budget ? "true" : "false", c.schedule);
    out += figure_fields(columns, c, c.within_latency_budget ? "true" : "false", true);
    out += ",\n";
  }
  return out;
}

std::string CsvGridReporter::render(const GridReport& r) const { return grid_to_csv(r.grid); }

}  // namespace shatter
