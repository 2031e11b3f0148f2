#include "harness/results/gbench_reporter.h"

#include "harness/results/sample_statistics.h"

#include <fmt/core.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace shatter {

nlohmann::ordered_json grid_to_gbench_json(const GridResult& grid, const std::string& case_name,
                                           const RunContext& context) {
  using Json = nlohmann::ordered_json;
  Json benchmarks = Json::array();
  int family = 0;
  // The cell's figures shown as counters (none: the entries carry no counters).
  std::vector<std::pair<std::string, std::vector<double>>> counters;
  const auto add = [&](const std::string& name, const std::vector<double>& per_rep) {
    for (std::size_t k = 0; k < per_rep.size(); ++k) {
      benchmarks.push_back({{"name", name},
                            {"family_index", family},
                            {"per_family_instance_index", 0},
                            {"run_name", name},
                            {"run_type", "iteration"},
                            {"repetitions", static_cast<int>(per_rep.size())},
                            {"repetition_index", static_cast<int>(k)},
                            {"threads", 1},
                            {"iterations", grid.frames},
                            {"real_time", per_rep[k]},
                            {"cpu_time", per_rep[k]},
                            {"time_unit", "ms"}});
      for (const auto& [counter, values] : counters) benchmarks.back()[counter] = values[k];
    }
    const double median = median_of(per_rep);
    benchmarks.push_back({{"name", name + "_median"},
                          {"family_index", family},
                          {"per_family_instance_index", 0},
                          {"run_name", name},
                          {"run_type", "aggregate"},
                          {"repetitions", static_cast<int>(per_rep.size())},
                          {"threads", 1},
                          {"aggregate_name", "median"},
                          {"aggregate_unit", "time"},
                          {"iterations", static_cast<int>(per_rep.size())},
                          {"real_time", median},
                          {"cpu_time", median},
                          {"time_unit", "ms"}});
    for (const auto& [counter, values] : counters) benchmarks.back()[counter] = median_of(values);
    counters.clear();
    ++family;
  };
  for (const GridCell& c : grid.cells) {
    const std::string prefix = fmt::format("{}/{}x{}/", case_name, c.prefracture, c.runtime);
    if (!c.failed.empty()) {  // Google Benchmark's form of a benchmark that could not run
      benchmarks.push_back({{"name", prefix + "worst_frame"},
                            {"family_index", family++},
                            {"per_family_instance_index", 0},
                            {"run_name", prefix + "worst_frame"},
                            {"run_type", "iteration"},
                            {"repetitions", grid.repetitions},
                            {"repetition_index", 0},
                            {"threads", 1},
                            {"iterations", 0},
                            {"real_time", 0},
                            {"cpu_time", 0},
                            {"time_unit", "ms"},
                            {"error_occurred", true},
                            {"error_message", c.failed}});
      continue;
    }
    std::vector<double> worst;
    for (const GridSample& s : c.samples) worst.push_back(s.worst_frame_ms);
    for (const Figure& f : c.samples.front().figures.figures()) {
      if ((f.spec.outputs & kFigureInGbench) == 0) continue;
      std::vector<double> values;
      for (const GridSample& s : c.samples) values.push_back(s.figures.value_or(f.spec.name, f.spec.fallback));
      counters.emplace_back(f.spec.name, std::move(values));
    }
    add(prefix + "worst_frame", worst);
    for (const Stage st : kAllStages) {
      std::vector<double> v;
      for (const GridSample& s : c.samples) v.push_back(s.stages_ms[static_cast<std::size_t>(st)]);
      if (std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; })) continue;
      add(prefix + std::string(stage_name(st)), v);
    }
  }
  Json ctx = {{"date", context.date},
              {"host_name", context.hostname},
              {"executable", "shatterbench grid"},
              {"num_cpus", context.cores},
              {"mhz_per_cpu", 0},
              {"cpu_scaling_enabled", false},
              {"caches", Json::array()},
              {"load_avg", Json::array()},
              {"library_build_type", context.build_type == "Debug" ? "debug" : "release"},
              {"shatterbench", to_json(context)}};
  return {{"context", ctx}, {"benchmarks", benchmarks}};
}

std::string GbenchGridReporter::render(const GridReport& r) const {
  return grid_to_gbench_json(r.grid, r.case_name, r.context).dump(1) + "\n";
}

}  // namespace shatter
