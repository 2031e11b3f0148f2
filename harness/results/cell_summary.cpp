#include "harness/results/cell_summary.h"

#include "harness/results/cell_checks.h"

#include <algorithm>

namespace shatter {
namespace {

double median_over(const std::vector<GridSample>& samples, double GridSample::*field) {
  std::vector<double> v;
  for (const GridSample& s : samples) v.push_back(s.*field);
  return median_of(v);
}

StageTimes median_stages(const std::vector<GridSample>& samples, StageTimes GridSample::*field) {
  StageTimes out{};
  std::vector<double> v;
  for (std::size_t k = 0; k < kStageCount; ++k) {
    v.clear();
    for (const GridSample& s : samples) v.push_back((s.*field)[k]);
    out[k] = median_of(v);
  }
  return out;
}

}  // namespace

void summarise_cell_figures(GridCell& cell, double latency_budget_ms) {
  std::vector<const FigureRecord*> records;
  for (const GridSample& s : cell.samples) records.push_back(&s.figures);
  cell.summaries = summarise_figures(records);
  cell.within_latency_budget = cell.summaries.value_or("latency_ms", 0.0) <= latency_budget_ms;
}

void summarise_cell(GridCell& cell, double budget_ms, double latency_budget_ms) {
  std::vector<double> frames;
  for (const GridSample& s : cell.samples) frames.insert(frames.end(), s.frame_ms.begin(), s.frame_ms.end());
  cell.frame_ms = sample_statistics(frames);
  cell.worst_frame_ms = median_over(cell.samples, &GridSample::worst_frame_ms);
  cell.event_ms = median_over(cell.samples, &GridSample::event_ms);
  cell.stages_ms = median_stages(cell.samples, &GridSample::stages_ms);
  cell.setup_ms = median_stages(cell.samples, &GridSample::setup_ms);
  cell.within_budget = cell.worst_frame_ms <= budget_ms;
  summarise_cell_figures(cell, latency_budget_ms);
}

void add_cell_stages(GridCell& cell, const std::vector<std::string>& run, const std::vector<StageSkip>& skipped) {
  for (const std::string& name : run)
    if (std::find(cell.stages_run.begin(), cell.stages_run.end(), name) == cell.stages_run.end())
      cell.stages_run.push_back(name);
  // Keep data-flow order.
  std::vector<std::string> ordered;
  for (const Stage s : kAllStages) {
    const std::string name(stage_name(s));
    if (std::find(cell.stages_run.begin(), cell.stages_run.end(), name) != cell.stages_run.end())
      ordered.push_back(name);
  }
  cell.stages_run = std::move(ordered);
  for (const StageSkip& skip : skipped) {
    const bool known = std::any_of(cell.stages_skipped.begin(), cell.stages_skipped.end(), [&](const StageSkip& s) {
      return s.stage == skip.stage && s.reason == skip.reason;
    });
    if (!known) cell.stages_skipped.push_back(skip);
  }
}

void add_cell_accuracy(CellAccuracy& into, const CellAccuracy& other) {
  into.prefracture_volume_error = std::max(into.prefracture_volume_error, other.prefracture_volume_error);
  into.prefracture_partition_error = std::max(into.prefracture_partition_error, other.prefracture_partition_error);
  into.prefracture_all_closed = into.prefracture_all_closed && other.prefracture_all_closed;
  into.prefracture_min_fragment_volume =
      std::min(into.prefracture_min_fragment_volume, other.prefracture_min_fragment_volume);
  into.runtime_volume_error = std::max(into.runtime_volume_error, other.runtime_volume_error);
  into.runtime_partition_error = std::max(into.runtime_partition_error, other.runtime_partition_error);
  into.runtime_all_closed = into.runtime_all_closed && other.runtime_all_closed;
  // 0 stands for "no runtime pieces".
  if (into.runtime_min_fragment_volume == 0.0 || other.runtime_min_fragment_volume == 0.0)
    into.runtime_min_fragment_volume = std::max(into.runtime_min_fragment_volume, other.runtime_min_fragment_volume);
  else
    into.runtime_min_fragment_volume = std::min(into.runtime_min_fragment_volume, other.runtime_min_fragment_volume);
  into.solver_converged = into.solver_converged && other.solver_converged;
  into.solver_residual = std::max(into.solver_residual, other.solver_residual);
}

bool GridResult::passed() const {
  return std::all_of(cells.begin(), cells.end(), [](const GridCell& c) {
    return c.failed.empty() && c.within_budget && c.within_latency_budget && failed_cell_checks(c).empty();
  });
}

}  // namespace shatter
