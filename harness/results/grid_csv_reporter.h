#pragma once
/// A grid's results as CSV, one row per cell (docs/results.md): the twin of the results JSON.

#include "harness/results/grid_reporter.h"

namespace shatter {

/// One header line and one line per cell; times in ms. After the typed timings and accuracy come the
/// figure summaries that have a CSV column (`csv_order`), then `within_latency_budget` at its place
/// among them; the last column, `failed`, is empty for a cell that ran. A failed cell has its
/// settings, verdicts and reason only.
class CsvGridReporter final : public GridReporter {
 public:
  /// "csv".
  [[nodiscard]] std::string_view format() const override { return "csv"; }
  /// grid_to_csv of the report's grid.
  [[nodiscard]] std::string render(const GridReport& report) const override;
};

/// The CSV of `grid` (see CsvGridReporter).
std::string grid_to_csv(const GridResult& grid);

}  // namespace shatter
