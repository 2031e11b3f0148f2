#include "harness/results/gbench_reporter.h"

#include "harness/results/sample_statistics.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kNanosecondsPerMs = 1e6;

/// One figure of a cell over its repetitions: wall and CPU time per iteration (ns), and counters.
struct Series {
  std::string name;
  int iterations = 1;
  std::vector<double> real_ns;
  std::vector<double> cpu_ns;
  std::vector<std::pair<std::string, std::vector<double>>> counters;
};

double mean_of(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

/// The sample standard deviation (n - 1), as Google Benchmark's stddev aggregate; 0 below 2 samples.
double stddev_of(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean_of(v);
  double sum = 0.0;
  for (const double x : v) sum += (x - m) * (x - m);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

/// The coefficient of variation; 0 when the mean is 0.
double cv_of(const std::vector<double>& v) {
  const double m = mean_of(v);
  return m == 0.0 ? 0.0 : stddev_of(v) / m;
}

class Writer {
 public:
  Writer(int repetitions, bool aggregates_only) : repetitions_(repetitions), aggregates_only_(aggregates_only) {}

  void add(const Series& s) {
    if (!aggregates_only_)
      for (std::size_t k = 0; k < s.real_ns.size(); ++k) {
        Json b = entry(s.name, s.name, "iteration", s.iterations, s.real_ns[k], s.cpu_ns[k]);
        b["repetition_index"] = static_cast<int>(k);
        for (const auto& [counter, values] : s.counters) b[counter] = values[k];
        benchmarks_.push_back(std::move(b));
      }
    using Stat = double (*)(const std::vector<double>&);
    const std::pair<const char*, Stat> aggregates[] = {
        {"mean", &mean_of}, {"median", [](const std::vector<double>& v) { return median_of(v); }},
        {"stddev", &stddev_of}, {"cv", &cv_of}};
    for (const auto& [aggregate, stat] : aggregates) {
      Json b = entry(s.name + "_" + aggregate, s.name, "aggregate", static_cast<int>(s.real_ns.size()),
                     stat(s.real_ns), stat(s.cpu_ns));
      b["aggregate_name"] = aggregate;
      b["aggregate_unit"] = std::string(aggregate) == "cv" ? "percentage" : "time";
      for (const auto& [counter, values] : s.counters) b[counter] = stat(values);
      benchmarks_.push_back(std::move(b));
    }
    ++family_;
  }

  void add_failed(const std::string& name, const std::string& reason) {
    Json b = entry(name, name, "iteration", 0, 0.0, 0.0);
    b["repetition_index"] = 0;
    b["error_occurred"] = true;
    b["error_message"] = reason;
    benchmarks_.push_back(std::move(b));
    ++family_;
  }

  Json take() { return std::move(benchmarks_); }

 private:
  Json entry(const std::string& name, const std::string& run_name, const char* run_type, int iterations,
             double real_ns, double cpu_ns) const {
    return Json{{"name", name},
                {"family_index", family_},
                {"per_family_instance_index", 0},
                {"run_name", run_name},
                {"run_type", run_type},
                {"repetitions", repetitions_},
                {"threads", 1},
                {"iterations", iterations},
                {"real_time", real_ns},
                {"cpu_time", cpu_ns},
                {"time_unit", "ns"}};
  }

  int repetitions_;
  bool aggregates_only_;
  int family_ = 0;
  Json benchmarks_ = Json::array();
};

}  // namespace

nlohmann::ordered_json grid_to_gbench_json(const GridResult& grid, const std::string& case_name,
                                           const RunContext& context, bool aggregates_only) {
  Writer writer(grid.repetitions, aggregates_only);
  const double frames = static_cast<double>(std::max(grid.frames, 1));
  for (const GridCell& c : grid.cells) {
    const std::string prefix = fmt::format("{}/{}x{}/", case_name, c.prefracture, c.runtime);
    if (!c.failed.empty() || c.samples.empty()) {  // Google Benchmark's form of a benchmark that could not run
      writer.add_failed(prefix + "worst_frame", c.failed.empty() ? std::string("no samples") : c.failed);
      continue;
    }
    Series worst{prefix + "worst_frame", 1, {}, {}, {}};
    for (const GridSample& s : c.samples) {
      worst.real_ns.push_back(s.worst_frame_ms * kNanosecondsPerMs);
      worst.cpu_ns.push_back(s.worst_frame_cpu_ms * kNanosecondsPerMs);
    }
    for (const Figure& f : c.samples.front().figures.figures()) {
      if ((f.spec.outputs & kFigureInGbench) == 0) continue;
      std::vector<double> values;
      for (const GridSample& s : c.samples) values.push_back(s.figures.value_or(f.spec.name, f.spec.fallback));
      worst.counters.emplace_back(f.spec.name, std::move(values));
    }
    writer.add(worst);
    for (const Stage st : kAllStages) {
      const auto i = static_cast<std::size_t>(st);
      Series stage{prefix + std::string(stage_name(st)), grid.frames, {}, {}, {}};
      for (const GridSample& s : c.samples) {
        stage.real_ns.push_back(s.stages_ms[i] / frames * kNanosecondsPerMs);
        stage.cpu_ns.push_back(s.stages_cpu_ms[i] / frames * kNanosecondsPerMs);
      }
      if (std::all_of(stage.real_ns.begin(), stage.real_ns.end(), [](double x) { return x == 0.0; })) continue;
      writer.add(stage);
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
  return {{"context", ctx}, {"benchmarks", writer.take()}};
}

std::string GbenchGridReporter::render(const GridReport& r) const {
  return grid_to_gbench_json(r.grid, r.case_name, r.context, aggregates_only_).dump(1) + "\n";
}

}  // namespace shatter
