#pragma once
/// A grid in Google Benchmark's JSON output schema (`context` + `benchmarks`), so that its
/// tools/compare.py and CI benchmark actions read shatterbench results (`grid --gbench FILE`, written
/// beside the native results; docs/results.md, "Google Benchmark JSON").
///
/// Mapping, per cell, with names unique within a file:
///   - `<case>/<prefracture>x<runtime>/worst_frame`: the gated figure, one frame, so `iterations` 1;
///     `real_time` the slowest frame's wall time, `cpu_time` the thread CPU time of the frame with the
///     most of it (the CPU clock, not a copy of the wall time);
///   - `<case>/<prefracture>x<runtime>/<stage>`: the stage's time per frame (its time inside the
///     repetition's frames divided by the frame count, which is `iterations`, as Google Benchmark
///     reports a per-iteration time over that many iterations); `cpu_time` the same from the thread
///     CPU clock. Stages that took no time in any repetition are left out.
/// Each has one `run_type` "iteration" entry per repetition (`repetitions`, `repetition_index`) and the
/// aggregates Google Benchmark writes for repetitions: `_mean`, `_median`, `_stddev` (time) and `_cv`
/// (a ratio, `aggregate_unit` "percentage"). Times are in nanoseconds (`time_unit` "ns", Google
/// Benchmark's default): compare.py prints times without decimals, so milliseconds would show a
/// 2.6 ms frame as "3" and microseconds a stage of 0.3 us per frame as "0". With
/// `aggregates_only` (`--gbench-aggregates-only`) only the aggregates are written, as
/// `--benchmark_report_aggregates_only` does. A failed cell (`grid --timeout`, a fracturer that threw)
/// is one `worst_frame` entry with `error_occurred` true and `error_message` its reason. Each named
/// figure whose spec asks for Google Benchmark (kFigureInGbench) is a user counter of the cell's
/// `worst_frame` entries: its value per repetition, and its aggregate in each aggregate entry. The
/// context holds Google Benchmark's keys (`date`, `host_name`, `executable`, `num_cpus`,
/// `mhz_per_cpu`, `cpu_scaling_enabled`, `caches`, `library_build_type`) and shatterbench's own context.

#include "harness/results/grid_reporter.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shatter {

/// Google Benchmark's JSON of a grid.
class GbenchGridReporter final : public GridReporter {
 public:
  explicit GbenchGridReporter(bool aggregates_only = false) : aggregates_only_(aggregates_only) {}
  /// "gbench" or "gbench-aggregates".
  [[nodiscard]] std::string_view format() const override { return aggregates_only_ ? "gbench-aggregates" : "gbench"; }
  /// grid_to_gbench_json of the report, as text (`dump(1)` and a line break).
  [[nodiscard]] std::string render(const GridReport& report) const override;

 private:
  bool aggregates_only_;
};

/// `grid` for case `case_name` in Google Benchmark's schema; only the aggregates with `aggregates_only`.
nlohmann::ordered_json grid_to_gbench_json(const GridResult& grid, const std::string& case_name,
                                           const RunContext& context, bool aggregates_only = false);

}  // namespace shatter
