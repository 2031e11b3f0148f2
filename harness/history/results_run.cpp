#include "harness/history/results_run.h"

#include "algorithms/core/bounded_read.h"
#include "harness/limits.h"
#include "harness/results/fnv1a.h"
#include "harness/results/grid_reader.h"
#include "harness/results/json_finite.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <string_view>
#include <unordered_map>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

std::string content_id(const std::string& text) {
  return fmt::format("{:016x}{:08x}", fnv1a(text), static_cast<std::uint32_t>(text.size()));
}

/// Figures a run reports about itself that are costs: a larger value is worse. Every other figure of
/// a grid sample (fragments, bodies, particles) describes the run and never regresses.
Better figure_direction(std::string_view name, std::string_view unit) {
  if (unit == "ms") return Better::lower;
  if (name.ends_with("_error") || name.ends_with("mismatch") || name.ends_with("volume_loss") || name == "residual" ||
      name == "solver.residual")
    return Better::lower;
  return Better::none;
}

/// Largest magnitude a stored value may have: the analysis's sums of squares stay finite below it.
constexpr double kMaxStoredMagnitude = 1e150;

struct Builder {
  RunRecord& run;
  std::string case_name;  ///< the series' case: the run's, or an accuracy point's case, or a table row's mesh
  std::string error;      ///< the first value out of range, named by its series
  std::unordered_map<std::int64_t, std::size_t> index;  ///< series id -> its measurement
  void add(const std::string& subject, const std::string& what, const std::string& metric, const std::string& unit,
           Better better, std::vector<double> samples) {
    if (samples.empty()) return;
    for (double v : samples)
      if (!std::isfinite(v)) return;  // a figure a run could not measure is left out, never stored as NaN
    for (double v : samples)
      if (std::abs(v) > kMaxStoredMagnitude && error.empty())
        error = fmt::format("{} {} {} {}: {:g} is out of range (magnitude at most {:g})", case_name, subject, what, metric,
                            v, kMaxStoredMagnitude);
    SeriesKey key{run.kind, case_name, run.fingerprint, subject, what, metric, unit, better};
    // One series twice in a file (a table with a count given twice): more samples of it.
    const auto [at, fresh] = index.emplace(series_id(key), run.measurements.size());
    if (!fresh) {
      std::vector<double>& kept = run.measurements[at->second].samples;
      kept.insert(kept.end(), samples.begin(), samples.end());
      return;
    }
    run.measurements.push_back(Measurement{std::move(key), std::move(samples)});
  }
};

void add_grid_series(const StoredGrid& g, Builder& b) {
  const bool instructions = g.metric == "instructions";
  for (const GridCell& cell : g.grid.cells) {
    if (!cell.failed.empty() || cell.samples.empty()) continue;
    std::string subject = fmt::format("{} x {} {}/{}/{}", cell.prefracture, cell.runtime, cell.prefracturer,
                                      cell.fracturer, cell.stress);
    if (cell.schedule != "immediate") subject += " " + cell.schedule;
    auto per_sample = [&](auto get) {
      std::vector<double> v;
      for (const GridSample& s : cell.samples) v.push_back(get(s));
      return v;
    };
    if (instructions) {
      b.add(subject, "worst frame", "instructions", "instructions", Better::lower,
            per_sample([](const GridSample& s) { return s.instructions ? s.instructions->worst_frame : NAN; }));
      b.add(subject, "event frame", "instructions", "instructions", Better::lower,
            per_sample([](const GridSample& s) { return s.instructions ? s.instructions->event : NAN; }));
    } else {
      b.add(subject, "worst frame", "time_ms", "ms", Better::lower, per_sample([](const GridSample& s) { return s.worst_frame_ms; }));
      b.add(subject, "worst frame", "cpu_ms", "ms", Better::lower,
            per_sample([](const GridSample& s) { return s.worst_frame_cpu_ms; }));
      b.add(subject, "event frame", "time_ms", "ms", Better::lower, per_sample([](const GridSample& s) { return s.event_ms; }));
      if (cell.samples.front().calibration_ms > 0.0)
        b.add(subject, "calibration", "cpu_ms", "ms", Better::none,
              per_sample([](const GridSample& s) { return s.calibration_ms; }));
    }
    for (const std::string& name : cell.stages_run) {
      int index = -1;
      for (Stage st : kAllStages)
        if (stage_name(st) == name) index = static_cast<int>(st);
      if (index < 0) continue;
      const std::string what = "stage " + name;
      if (instructions) {
        b.add(subject, what, "instructions", "instructions", Better::lower, per_sample([&](const GridSample& s) {
                return s.instructions ? s.instructions->stages[index] : NAN;
              }));
        continue;
      }
      b.add(subject, what, "time_ms", "ms", Better::lower, per_sample([&](const GridSample& s) { return s.stages_ms[index]; }));
      b.add(subject, what, "cpu_ms", "ms", Better::lower, per_sample([&](const GridSample& s) { return s.stages_cpu_ms[index]; }));
      if (cell.setup_ms[index] > 0.0)
        b.add(subject, "setup " + name, "time_ms", "ms", Better::lower,
              per_sample([&](const GridSample& s) { return s.setup_ms[index]; }));
    }
    if (!instructions)
      for (const Figure& f : cell.samples.front().figures.figures()) {
        if (f.spec.kind == FigureKind::flag) continue;
        b.add(subject, "figure", f.spec.name, f.spec.unit, figure_direction(f.spec.name, f.spec.unit),
              per_sample([&](const GridSample& s) { return s.figures.value_or(f.spec.name, NAN); }));
      }
    const CellAccuracy& a = cell.accuracy;
    b.add(subject, "accuracy", "prefracture_volume_error", "", Better::lower, {a.prefracture_volume_error});
    b.add(subject, "accuracy", "prefracture_partition_error", "", Better::lower, {a.prefracture_partition_error});
    b.add(subject, "accuracy", "runtime_volume_error", "", Better::lower, {a.runtime_volume_error});
    b.add(subject, "accuracy", "runtime_partition_error", "", Better::lower, {a.runtime_partition_error});
    b.add(subject, "accuracy", "solver_residual", "", Better::lower, {a.solver_residual});
  }
}

/// Reads `j[key]` as T, or throws with the key's path.
struct BadKey : std::runtime_error {
  using std::runtime_error::runtime_error;
};
const Json& at(const Json& j, const std::string& key, const std::string& path) {
  if (!j.is_object() || !j.contains(key)) throw BadKey(fmt::format("{}{}: missing", path.empty() ? "" : path + ".", key));
  return j.at(key);
}
std::string text_at(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_string()) throw BadKey(fmt::format("{}{}: expected a string", path.empty() ? "" : path + ".", key));
  return v.get<std::string>();
}
std::vector<double> numbers_at(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_array()) throw BadKey(fmt::format("{}.{}: expected an array of numbers", path, key));
  std::vector<double> out;
  for (const Json& x : v) {
    if (!x.is_number()) throw BadKey(fmt::format("{}.{}: expected an array of numbers", path, key));
    out.push_back(x.get<double>());
  }
  return out;
}

/// Every numeric figure of `figures` (an object), as one-sample series.
void add_figures(const Json& figures, const std::string& subject, const std::string& what, Builder& b) {
  if (!figures.is_object()) return;
  for (const auto& [name, v] : figures.items()) {
    if (!v.is_number() || v.is_boolean()) continue;
    b.add(subject, what, name, "", figure_direction(name, ""), {v.get<double>()});
  }
}

void add_accuracy_series(const Json& j, Builder& b) {
  const Json& points = at(j, "points", "");
  if (!points.is_array()) throw BadKey("points: expected an array");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string path = fmt::format("points[{}]", i);
    const Json& p = points[i];
    const std::string family = text_at(p, "family", path);
    b.case_name = text_at(p, "case", path);
    const std::string subject = fmt::format("{} {}", text_at(p, "algorithm", path), text_at(p, "knob", path));
    b.add(subject, family, "time_ms", "ms", Better::lower, numbers_at(p, "samples_ms", path));
    if (const Json& e = at(p, "error", path); e.is_number()) b.add(subject, family, "error", "", Better::lower, {e.get<double>()});
    add_figures(p.value("figures", Json::object()), subject, family, b);
  }
}

void add_table_series(const Json& j, Builder& b) {
  const Json& rows = at(j, "rows", "");
  if (!rows.is_array()) throw BadKey("rows: expected an array");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string path = fmt::format("rows[{}]", i);
    const Json& r = rows[i];
    const Json& requested = at(r, "fragments", path);
    if (!requested.is_number_integer()) throw BadKey(path + ".fragments: expected an integer");
    b.case_name = text_at(r, "mesh", path);
    if (!r.contains("samples_ms")) continue;  // a row the fracturer refused or failed: nothing measured
    const std::string subject = fmt::format("{} {} fragments", text_at(r, "algorithm", path), requested.get<std::int64_t>());
    b.add(subject, "fracture", "time_ms", "ms", Better::lower, numbers_at(r, "samples_ms", path));
    add_figures(r.value("figures", Json::object()), subject, "fracture", b);
  }
}

}  // namespace

Result<RunRecord> run_from_results_text(const std::string& text, const std::string& source) {
  Result<Json> parsed = parse_results_json(text, source);
  if (!parsed) return parsed.error();
  const Json& j = *parsed;
  RunRecord run;
  run.id = content_id(text);
  run.source = std::filesystem::path(source).filename().string();
  const bool grid = j.is_object() && j.contains("cells");
  const std::string kind = j.is_object() ? j.value("kind", std::string{}) : std::string{};
  if (!grid && kind != "accuracy" && kind != "table")
    return Error{source + ": not a shatterbench results file (a grid's has `cells`, an accuracy or table file its `kind`)"};
  Builder b{run, {}, {}, {}};
  if (grid) {
    Result<StoredGrid> g = grid_results_from_json(j, source);
    if (!g) return g.error();
    run.kind = "grid";
    run.case_name = g->case_name;
    b.case_name = run.case_name;
    run.fingerprint = g->context.fingerprint;
    run.machine = g->context.hostname;
    run.context_json = to_json(g->context).dump();
    Json settings = Json::object();
    settings["case"] = g->case_block;
    for (const char* key : {"metric", "budget_ms", "latency_budget_ms", "repetitions", "frames", "no_skip", "same_seed", "threads"})
      if (j.contains(key)) settings[key] = j[key];
    run.settings_json = settings.dump();
    // Runs that compare refuses to mix (another case, frame count, threads, seeds, budget) are other
    // series: the build's fingerprint and a hash of the case and settings, repetitions left out
    // (more repetitions are more samples of the same series).
    nlohmann::json setup = settings;
    setup.erase("repetitions");
    run.fingerprint += "-" + content_id(setup.dump()).substr(0, 8);
    run.passed = g->grid.passed();
    add_grid_series(*g, b);
  } else {
    try {
      Result<RunContext> context = context_from_json(at(j, "context", ""));
      if (!context) return Error{source + ": " + context.error().message};
      run.kind = kind;
      run.fingerprint = context->fingerprint;
      run.machine = context->hostname;
      run.context_json = to_json(*context).dump();
      Json settings = Json::object();
      for (const char* key : {"repetitions", "cases", "meshes"})
        if (j.contains(key)) settings[key] = j[key];
      run.settings_json = settings.dump();
      if (j.contains("passed") && !j["passed"].is_boolean()) throw BadKey("passed: expected true or false");
      run.passed = j.value("passed", true);
      if (kind == "accuracy") {
        run.case_name = "accuracy";
        add_accuracy_series(j, b);
      } else {
        run.case_name = "table";
        add_table_series(j, b);
      }
    } catch (const BadKey& e) {
      return Error{source + ": " + e.what()};
    } catch (const nlohmann::json::exception& e) {
      return Error{source + ": " + e.what()};
    }
  }
  if (!b.error.empty()) return Error{source + ": " + b.error};
  if (run.fingerprint.empty()) return Error{source + ": context.fingerprint: empty (the run cannot be put in a series)"};
  if (run.measurements.empty()) return Error{source + ": the results hold no measurement (every cell failed?)"};
  return run;
}

Result<RunRecord> read_results_run(const std::filesystem::path& path) {
  const Result<std::string> text = read_file_bounded(path, kMaxResultsFileBytes, "results file");
  if (!text) return text.error();
  return run_from_results_text(*text, path.string());
}

}  // namespace shatter
