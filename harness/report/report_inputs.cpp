#include "harness/report/report_inputs.h"

#include "algorithms/core/bounded_read.h"
#include "harness/limits.h"
#include "harness/results/json_finite.h"
#include "harness/report/recorded_frames_input.h"

#include <nlohmann/json.hpp>

#include <fmt/core.h>

#include <cmath>
#include <limits>

namespace shatter {
namespace {

using Json = nlohmann::json;

/// A key check failed: the message is "<key path>: <what>".
struct KeyError {
  std::string message;
};

const Json& at(const Json& object, const std::string& key, const std::string& path) {
  if (!object.is_object()) throw KeyError{path + ": expected an object"};
  const auto it = object.find(key);
  if (it == object.end()) throw KeyError{(path.empty() ? key : path + "." + key) + ": missing required key"};
  return *it;
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

double number(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (!v.is_number() || !std::isfinite(v.get<double>())) throw KeyError{join(path, key) + ": expected a finite number"};
  return v.get<double>();
}

std::optional<double> number_or_null(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (v.is_null()) return std::nullopt;
  return number(object, key, path);
}

int integer(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (!v.is_number_integer()) throw KeyError{join(path, key) + ": expected an integer"};
  return v.get<int>();
}

std::string text(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (!v.is_string()) throw KeyError{join(path, key) + ": expected a string"};
  return v.get<std::string>();
}

bool boolean(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (!v.is_boolean()) throw KeyError{join(path, key) + ": expected true or false"};
  return v.get<bool>();
}

const Json& array(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (!v.is_array() || v.empty()) throw KeyError{join(path, key) + ": expected a non-empty array"};
  return v;
}

StageTimes stages(const Json& object, const std::string& key, const std::string& path) {
  const Json& v = at(object, key, path);
  if (!v.is_object()) throw KeyError{join(path, key) + ": expected an object"};
  StageTimes out;
  for (const auto& [name, value] : v.items()) {
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      throw KeyError{join(join(path, key), name) + ": expected a finite number"};
    out.emplace_back(name, value.get<double>());
  }
  return out;
}

ReportGrid read_grid(const Json& j, const std::string& file) {
  ReportGrid g;
  g.file = file;
  g.case_name = text(at(j, "case", ""), "name", "case");
  g.budget_ms = number(j, "budget_ms", "");
  if (j.contains("frames")) g.frames = integer(j, "frames", "");
  const Json& cells = array(j, "cells", "");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::string path = fmt::format("cells[{}]", i);
    const Json& c = cells[i];
    ReportCell cell;
    cell.prefracture = integer(c, "prefracture", path);
    cell.runtime = integer(c, "runtime", path);
    if (c.contains("failed")) {  // timed out or crashed: no figures
      cell.failed = text(c, "failed", path);
      cell.within_budget = false;
      g.cells.push_back(std::move(cell));
      continue;
    }
    cell.worst_frame_ms = number(c, "worst_frame_ms", path);
    cell.within_budget = boolean(c, "within_budget", path);
    cell.stages_ms = stages(c, "stages_ms", path);
    if (c.contains("fracturer")) cell.fracturer = text(c, "fracturer", path);
    if (c.contains("stress")) cell.stress = text(c, "stress", path);
    if (c.contains("samples")) {
      const Json& samples = array(c, "samples", path);
      for (std::size_t k = 0; k < samples.size(); ++k)
        cell.sample_stages_ms.push_back(stages(samples[k], "stages_ms", fmt::format("{}.samples[{}]", path, k)));
    }
    g.cells.push_back(std::move(cell));
  }
  return g;
}

ReportAccuracy read_accuracy(const Json& j, const std::string& file) {
  ReportAccuracy a;
  a.file = file;
  const Json& points = array(j, "points", "");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string path = fmt::format("points[{}]", i);
    const Json& e = points[i];
    AccuracyPoint p;
    p.family = text(e, "family", path);
    if (p.family != "fracture" && p.family != "stress" && p.family != "colliders" && p.family != "cascade")
      throw KeyError{path + ".family: expected fracture, stress, colliders or cascade"};
    p.case_name = text(e, "case", path);
    p.algorithm = text(e, "algorithm", path);
    p.knob = text(e, "knob", path);
    p.time_ms = number_or_null(e, "time_ms", path).value_or(std::numeric_limits<double>::quiet_NaN());
    p.error = number_or_null(e, "error", path);
    p.pareto = boolean(e, "pareto", path);
    if (e.contains("knobs")) {
      if (!e["knobs"].is_object()) throw KeyError{path + ".knobs: expected an object"};
      p.knobs = e["knobs"];
    }
    if (e.contains("figures")) {
      if (!e["figures"].is_object()) throw KeyError{path + ".figures: expected an object"};
      if (e["figures"].contains("failed") && !e["figures"]["failed"].is_string())
        throw KeyError{path + ".figures.failed: expected a string"};
      p.figures = e["figures"];
    }
    a.points.push_back(std::move(p));
  }
  return a;
}

ReportStability read_stability(const Json& j, const std::string& file) {
  ReportStability s;
  s.file = file;
  const Json& rows = at(j, "results", "");
  if (!rows.is_array()) throw KeyError{"results: expected an array"};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    HazardResult r;
    if (!from_json(rows[i], r))
      throw KeyError{fmt::format("results[{}]: expected a stability verdict (hazard, algorithm, kind, outcome, detail, "
                                 "worst_error, fragments, time_ms)", i)};
    s.results.push_back(std::move(r));
  }
  return s;
}

ReportTable read_table(const Json& j, const std::string& file) {
  ReportTable t;
  t.file = file;
  const Json& rows = at(j, "rows", "");
  if (!rows.is_array()) throw KeyError{"rows: expected an array"};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string path = fmt::format("rows[{}]", i);
    const Json& r = rows[i];
    ReportTableRow row;
    row.mesh = text(r, "mesh", path);
    row.algorithm = text(r, "algorithm", path);
    row.fragments = integer(r, "fragments", path);
    if (r.contains("refused")) {
      row.outcome = "refused: " + text(r, "refused", path);
    } else if (r.contains("failed")) {
      row.outcome = "failed: " + text(r, "failed", path);
    } else {
      row.outcome = fmt::format("{} fragments", integer(r, "produced", path));
      row.time_ms = number(r, "time_ms", path);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

void check_schema_version(const Json& j) {
  const auto it = j.find("schema_version");
  if (it == j.end()) return;  // stability results carry none
  if (!it->is_number_integer() || it->get<long long>() != kReportSchemaVersion)
    throw KeyError{fmt::format("schema_version {}: this shatterbench reads results of version {}", it->dump(),
                               kReportSchemaVersion)};
}

}  // namespace

Result<ReportInputs> read_report_inputs(std::span<const std::string> files) {
  ReportInputs inputs;
  std::uint64_t recording_bytes = 0;
  std::int64_t fragments = 0, triangles = 0;
  for (const std::string& file : files) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
      Result<std::vector<ReportFragments>> folders = find_fragments_folders(file);
      if (!folders) return folders.error();
      for (ReportFragments& f : *folders) {
        fragments += static_cast<std::int64_t>(f.fragments);
        triangles += static_cast<std::int64_t>(f.triangles);
        if (fragments > kMaxReportFragments || triangles > kMaxReportTriangles)
          return Error{fmt::format("{}: the 3D views would hold {} fragments and {} triangles, past the report's limit "
                                   "of {} and {} (docs/report.md, Limits): give fewer folders or fracture a smaller mesh",
                                   f.folder, fragments, triangles, kMaxReportFragments, kMaxReportTriangles)};
        inputs.fragments.push_back(std::move(f));
      }
      continue;
    }
    const Result<std::string> text = read_file_bounded(file, kMaxResultsFileBytes, "results file");
    if (!text) return text.error();
    Result<nlohmann::ordered_json> parsed = parse_results_json(*text, file);
    if (!parsed) return parsed.error();
    const Json j = Json(*parsed);
    if (const std::optional<std::string> key = first_non_finite(j))
      return Error{file + ": " + *key + ": a number that is not finite (too large for a double)"};
    try {
      if (!j.is_object()) throw KeyError{"top level: expected an object"};
      check_schema_version(j);
      const auto kind = j.find("kind");
      const std::string kind_text = kind != j.end() && kind->is_string() ? kind->get<std::string>() : std::string();
      if (j.contains("cells")) {
        inputs.grids.push_back(read_grid(j, file));
        Result<std::string> recorded = read_grid_recording(j, file, recording_bytes);
        if (!recorded) return recorded.error();
        inputs.grids.back().recorded_frames = std::move(*recorded);
        inputs.grids.back().document = std::move(*parsed);
      } else if (kind_text == "table") {
        inputs.tables.push_back(read_table(j, file));
        inputs.tables.back().document = std::move(*parsed);
      } else if (j.contains("points") || kind_text == "accuracy") {
        inputs.accuracies.push_back(read_accuracy(j, file));
        inputs.accuracies.back().document = std::move(*parsed);
      } else if (j.contains("results")) {
        inputs.stabilities.push_back(read_stability(j, file));
        inputs.stabilities.back().document = std::move(*parsed);
      } else {
        throw KeyError{"not a results file of grid (no cells), accuracy (no points), table (no kind \"table\") "
                       "or stability (no results)"};
      }
    } catch (const KeyError& e) {
      return Error{file + ": " + e.message};
    } catch (const Json::exception& e) {
      return Error{file + ": " + e.what()};
    }
  }
  return inputs;
}

}  // namespace shatter
