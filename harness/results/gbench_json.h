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
/// `error_message` its reason, as Google Benchmark writes a benchmark that skipped with an error. The
/// context holds Google Benchmark's keys (`date`, `host_name`, `executable`, `num_cpus`,
/// `mhz_per_cpu`, `cpu_scaling_enabled`, `caches`, `library_build_type`) and shatterbench's own context.

#include "harness/grid/grid_runner.h"
#include "harness/results/run_context.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shatter {

/// `grid` for case `case_name` in Google Benchmark's schema.
nlohmann::ordered_json grid_to_gbench_json(const GridResult& grid, const std::string& case_name,
                                           const RunContext& context);

}  // namespace shatter
