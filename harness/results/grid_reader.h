#pragma once
/// Reading a grid results JSON (docs/results.md) back, for `compare`, `merge` and `report`.

#include "algorithms/core/result.h"
#include "harness/results/grid_record.h"
#include "harness/results/run_context.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace shatter {

/// A results file as read.
struct StoredGrid {
  std::filesystem::path path;           ///< where it was read from
  RunContext context;                   ///< its `context`
  nlohmann::ordered_json case_block;    ///< its `case`, as written
  nlohmann::ordered_json input_block;   ///< its `input` (the solid and its repairs), null when absent
  /// Its `recorded_frames` block (the sidecar of `grid --record-frames`), null when absent; `path` is
  /// the sidecar's name in this file's folder (read_recorded_frames reads it).
  nlohmann::ordered_json recorded_frames_block;
  std::string case_name;                ///< `case.name`
  std::string metric = "time";          ///< `metric`: "time" or "instructions"
  GridResult grid;                      ///< budget, repetitions, frames, cells with samples
};

/// Reads `path`; a sample's `frame_stages_ms` is read and checked (one value >= 0 per frame, known
/// stage names), the worst-frame breakdowns derived from it are not (results/worst_frame.h gives them
/// again). Errors name the file and the key ("a.json: cells[3].samples[0].frame_ms: expected an
/// array of numbers"), for unreadable files, malformed JSON and an unknown `schema_version`.
Result<StoredGrid> read_grid_results(const std::filesystem::path& path);

/// Parses one cell object of a results file (grid_cell_to_json); `what` names it in errors, and
/// `latency_budget_ms` judges a cell whose file predates the latency keys.
Result<GridCell> grid_cell_from_json(const nlohmann::ordered_json& j, const std::string& what,
                                     double latency_budget_ms);

/// Parses an already loaded document; `what` names it in errors.
Result<StoredGrid> grid_results_from_json(const nlohmann::ordered_json& j, const std::string& what);

}  // namespace shatter
