#pragma once
/// A grid's results as the contract JSON (DESIGN.md section 8; schema in docs/results.md).

#include "harness/cases/case.h"
#include "harness/results/grid_reporter.h"

namespace shatter {

/// Version of the results schema written in `schema_version`; bumped on incompatible changes.
inline constexpr int kGridSchemaVersion = 1;

/// The results JSON (results_json_text: `dump(1)`'s layout, per-frame stage arrays on one line) and a line break.
class JsonGridReporter final : public GridReporter {
 public:
  /// "json".
  [[nodiscard]] std::string_view format() const override { return "json"; }
  /// grid_to_json of the report, as text.
  [[nodiscard]] std::string render(const GridReport& report) const override;
};

/// One cell as the results JSON holds it (docs/results.md): its settings, figures and samples, or for
/// a failed cell its settings and `failed`.
nlohmann::ordered_json grid_cell_to_json(const GridCell& cell);

/// The results JSON's `case` block of `c`.
nlohmann::ordered_json case_to_json(const Case& c);

/// The results JSON: `schema_version`, `context`, `case` (`case_block`, from case_to_json), `input`
/// (`input_block`, from input_solid_json, when not null), `budget_ms`, `repetitions`, `frames`, `no_skip`, `shard` (when a shard), `cell_timeout_s` (when
/// set), `passed`, `wall_s`, `recorded_frames` (when `grid.recorded_frames_file` is set), `cells`.
nlohmann::ordered_json grid_to_json(const GridResult& grid, const nlohmann::ordered_json& case_block,
                                    const RunContext& context, const nlohmann::ordered_json& input_block = nullptr);

/// Writes `figure` into `object` under its name, a dot nesting it in an object of that key.
void put_figure(nlohmann::ordered_json& object, const Figure& figure);

}  // namespace shatter
