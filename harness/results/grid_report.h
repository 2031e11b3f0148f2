#pragma once
/// A grid's results as the contract JSON (DESIGN.md section 8; schema in docs/results.md), as CSV (one
/// row per cell) and as the Markdown table printed on stdout.

#include "harness/cases/case.h"
#include "harness/grid/grid_runner.h"
#include "harness/results/run_context.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shatter {

/// Version of the results schema written in `schema_version`; bumped on incompatible changes.
inline constexpr int kGridSchemaVersion = 1;

/// One cell as the results JSON holds it (docs/results.md): its settings, figures and samples, or for
/// a failed cell its settings and `failed`.
nlohmann::ordered_json grid_cell_to_json(const GridCell& cell);

/// The results JSON's `case` block of `c`.
nlohmann::ordered_json case_to_json(const Case& c);

/// The results JSON: `schema_version`, `context`, `case` (`case_block`, from case_to_json),
/// `budget_ms`, `repetitions`, `frames`, `no_skip`, `shard` (when a shard), `cell_timeout_s` (when
/// set), `passed`, `wall_s`, `cells`.
nlohmann::ordered_json grid_to_json(const GridResult& grid, const nlohmann::ordered_json& case_block,
                                    const RunContext& context);

/// One header line and one line per cell; times in ms. The last column, `failed`, is empty for a cell
/// that ran; a failed cell has its settings, verdicts and reason only.
std::string grid_to_csv(const GridResult& grid);

/// The Markdown table: rows pre-fracture counts, columns runtime counts, each cell its worst frame in
/// ms, marked "**x.xx !**" when over budget ("**timeout after 2 s !**" when failed); followed by a
/// one-line verdict.
std::string grid_to_markdown(const GridResult& grid, const std::string& case_name);

/// The instruction-mode table: each cell the median over repetitions of its largest frame's retired
/// instructions, in millions, followed by the event frame's median.
std::string grid_instructions_markdown(const GridResult& grid, const std::string& case_name);

}  // namespace shatter
