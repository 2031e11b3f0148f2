#pragma once
/// A grid in Google Benchmark's JSON output schema (`context` + `benchmarks`), so that its
/// tools/compare.py and CI benchmark actions read shatterbench results.
///
/// Mapping: one benchmark run per cell, repetition and figure, named
/// `<case>/<prefracture>x<runtime>/worst_frame` (the gated figure) and
/// `<case>/<prefracture>x<runtime>/<stage>` (stage time inside frames), with `run_type` "iteration",
/// `repetitions`, `repetition_index`, `iterations` = frames, `real_time` = `cpu_time` = the figure in ms,
/// `time_unit` "ms"; plus one `run_type` "aggregate" entry per cell and figure with `aggregate_name`
/// "median". A failed cell (`grid --timeout`) is one `worst_frame` entry with `error_occurred` true and
/// `error_message` its reason, as Google Benchmark writes a benchmark that skipped with an error. Each
/// named figure whose spec asks for Google Benchmark (kFigureInGbench) is a user counter of the cell's
/// `worst_frame` entries: its value per repetition, and the median in the aggregate. The
/// context holds Google Benchmark's keys (`date`, `host_name`, `executable`, `num_cpus`,
/// `mhz_per_cpu`, `cpu_scaling_enabled`, `caches`, `library_build_type`) and shatterbench's own context.

#include "harness/results/grid_reporter.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shatter {

/// Google Benchmark's JSON of a grid.
class GbenchGridReporter final : public GridReporter {
 public:
  /// "gbench".
  [[nodiscard]] std::string_view format() const override { return "gbench"; }
  /// grid_to_gbench_json of the report, as text (`dump(1)` and a line break).
  [[nodiscard]] std::string render(const GridReport& report) const override;
};

/// `grid` for case `case_name` in Google Benchmark's schema.
nlohmann::ordered_json grid_to_gbench_json(const GridResult& grid, const std::string& case_name,
                                           const RunContext& context);

}  // namespace shatter
