#pragma once
/// One grid cell run in a forked child under a wall-time limit (`grid --timeout`): a cell that passes
/// the limit or crashes becomes a failed cell instead of hanging or ending the grid.
///
/// Design note: the child does the whole cell, every repetition, and times it itself, exactly as the
/// grid does without a limit; the fork, the pipe and the JSON round trip happen before and after the
/// measured runs, so they add nothing to a frame or a stage. The cell comes back as the results JSON's
/// own cell object (grid_json_reporter.h), whose doubles round-trip exactly, so a cell run in a child writes
/// the same results as one run in the process. Pages the child first writes after the fork are copied
/// then (copy-on-write); the parent's heap holds the prepared case and the cells already done, which
/// the child does not write, so those copies are few and fall mostly in the pre-fracture setup, which
/// runs before frame 0. A limit that is met kills the child (SIGKILL): nothing of it is kept but the
/// reason. docs/design.md, "Grid cell time limit", weighs this against a deadline checked per frame.

#include "algorithms/core/result.h"
#include "harness/results/grid_record.h"

#include <functional>
#include <string>

namespace shatter {

/// Runs `run` in a forked child killed after `timeout_s` seconds (> 0). Returns the cell `run` made;
/// `settings` (grid_cell_settings) with `failed` set to "timeout after S s" when the limit was met, or
/// to "crashed: <signal or exit status>" when the child died without a result; the error `run`
/// returned, unchanged. `latency_budget_ms` judges the cell read back, as the child judged it.
Result<GridCell> run_cell_isolated(const std::function<Result<GridCell>()>& run, const GridCell& settings,
                                   double timeout_s, double latency_budget_ms);

/// `settings` (grid_cell_settings) as a failed cell: no samples, over both budgets, `failed` = `reason`.
GridCell failed_grid_cell(const GridCell& settings, std::string reason);

}  // namespace shatter
