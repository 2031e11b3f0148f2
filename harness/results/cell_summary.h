#pragma once
/// A grid cell's summaries from its samples, and the joining of two cells' repetitions (a grid cell
/// run in several parts, `merge --repetitions`). The design note of grid_runner.h says which summary
/// each figure gets and why.

#include "harness/results/grid_record.h"

#include <string>
#include <vector>

namespace shatter {

/// Fills `cell`'s figure summaries (summarise_figures over its samples) and judges its `latency_ms`
/// summary against `latency_budget_ms`, ms.
void summarise_cell_figures(GridCell& cell, double latency_budget_ms);

/// Fills every summary of `cell` from its samples (frame statistics, medians over repetitions of the
/// worst frame, the event frame and each stage, the figure summaries) and judges it against
/// `budget_ms` and `latency_budget_ms`, ms.
void summarise_cell(GridCell& cell, double budget_ms, double latency_budget_ms);

/// Makes `into` the worst of the two accuracy figures (as if their repetitions had been one cell's).
void add_cell_accuracy(CellAccuracy& into, const CellAccuracy& other);

/// Adds the stage names `run` (kept in data-flow order, each once) and the skips `skipped` (each stage
/// and reason once, first seen first) to `cell`'s lists.
void add_cell_stages(GridCell& cell, const std::vector<std::string>& run, const std::vector<StageSkip>& skipped);

}  // namespace shatter
