#include "harness/results/grid_reader.h"

#include "algorithms/core/bounded_read.h"
#include "harness/limits.h"
#include "harness/results/cell_summary.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/json_finite.h"
#include "harness/results/run_figures.h"

#include <fmt/core.h>

#include <climits>
#include <cstdint>
#include <stdexcept>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

/// A parse failure with the path of the key that failed.
struct BadKey : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const Json& at(const Json& j, const std::string& key, const std::string& path) {
  if (!j.is_object()) throw BadKey(path + ": expected an object");
  const auto it = j.find(key);
  if (it == j.end()) throw BadKey(path + (path.empty() ? "" : ".") + key + ": missing");
  return *it;
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

double number(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_number()) throw BadKey(join(path, key) + ": expected a number");
  return v.get<double>();
}

/// An integer that fits an int (every count of the file; seeds are read by seed_value).
int integer(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_number_integer()) throw BadKey(join(path, key) + ": expected an integer");
  const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(INT_MAX)
                                           : v.get<std::int64_t>() >= INT_MIN && v.get<std::int64_t>() <= INT_MAX;
  if (!fits) throw BadKey(join(path, key) + ": integer out of range, got " + v.dump());
  return v.get<int>();
}

/// A seed: an integer in [0, 2^64 - 1].
std::uint64_t seed_value(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<std::int64_t>() < 0))
    throw BadKey(join(path, key) + ": expected an integer in [0, 2^64 - 1]");
  return v.get<std::uint64_t>();
}

bool boolean(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_boolean()) throw BadKey(join(path, key) + ": expected true or false");
  return v.get<bool>();
}

std::string text(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_string()) throw BadKey(join(path, key) + ": expected a string");
  return v.get<std::string>();
}

const Json& array(const Json& j, const std::string& key, const std::string& path) {
  const Json& v = at(j, key, path);
  if (!v.is_array()) throw BadKey(join(path, key) + ": expected an array");
  return v;
}

std::vector<double> numbers(const Json& j, const std::string& key, const std::string& path) {
  std::vector<double> out;
  for (const Json& v : array(j, key, path)) {
    if (!v.is_number()) throw BadKey(join(path, key) + ": expected an array of numbers");
    out.push_back(v.get<double>());
  }
  return out;
}

StageTimes stages(const Json& j, const std::string& key, const std::string& path) {
  StageTimes out{};
  const Json& o = at(j, key, path);
  for (const Stage s : kAllStages) {
    // `debris` came after schema version 1 was first written: a file without it had no debris.
    if (s == Stage::debris && o.is_object() && !o.contains(std::string(stage_name(s)))) continue;
    out[static_cast<std::size_t>(s)] = number(o, std::string(stage_name(s)), join(path, key));
  }
  return out;
}

InstructionCounts instructions(const Json& j, const std::string& path) {
  InstructionCounts c;
  c.stages = stages(j, "stages", path);
  c.setup = stages(j, "setup", path);
  c.frames = numbers(j, "frames", path);
  c.event = number(j, "event", path);
  c.worst_frame = number(j, "worst_frame", path);
  return c;
}

/// A sample's `frame_stages_ms`: per stage named, one number >= 0 per frame (`frames` of them); nullopt
/// in a file from before the key.
std::optional<FrameStageTimes> frame_stages(const Json& j, std::size_t frames, const std::string& path) {
  if (!j.contains("frame_stages_ms")) return std::nullopt;
  const std::string where = join(path, "frame_stages_ms");
  const Json& o = j.at("frame_stages_ms");
  if (!o.is_object()) throw BadKey(where + ": expected an object");
  FrameStageTimes out;
  for (auto it = o.begin(); it != o.end(); ++it) {
    const std::optional<Stage> stage = stage_from_name(it.key());
    if (!stage) throw BadKey(join(where, it.key()) + ": not a stage name");
    std::vector<double> values = numbers(o, it.key(), where);
    if (values.size() != frames)
      throw BadKey(fmt::format("{}: expected {} values (one per frame), got {}", join(where, it.key()), frames,
                               values.size()));
    for (const double ms : values)
      if (ms < 0.0) throw BadKey(join(where, it.key()) + ": expected times >= 0");
    out[static_cast<std::size_t>(*stage)] = std::move(values);
  }
  return out;
}

/// Keys of a sample that are not figures of its record (`worst_frame_stages_ms` is derived from
/// `frame_ms` and `frame_stages_ms`, so it is not read).
bool typed_sample_key(const std::string& key) {
  static const char* const typed[] = {"seed",           "frame_ms",       "frame_stages_ms",       "event_ms",
                                      "event_frame",    "worst_frame_ms", "worst_frame_stages_ms", "stages_ms",
                                      "setup_ms",       "cpu",            "calibration_ms",        "instructions"};
  for (const char* t : typed)
    if (key == t) return true;
  return false;
}

/// The value of figure `spec` at `key` of `j`, checked against its kind.
double figure_value(const Json& j, const std::string& key, const FigureSpec& spec, const std::string& path) {
  switch (spec.kind) {
    case FigureKind::integer: return integer(j, key, path);
    case FigureKind::flag: return boolean(j, key, path) ? 1.0 : 0.0;
    case FigureKind::number: return number(j, key, path);
  }
  return 0.0;
}

/// A figure this build does not know, from its JSON value: its kind from the value's type, shown in
/// every output, summarised by median when `summarised` (its cell holds a summary of it).
FigureSpec unknown_figure(const std::string& name, const Json& v, bool summarised, const std::string& path) {
  FigureSpec spec;
  spec.name = name;
  if (v.is_boolean()) spec.kind = FigureKind::flag;
  else if (v.is_number_integer()) spec.kind = FigureKind::integer;
  else if (v.is_number()) spec.kind = FigureKind::number;
  else throw BadKey(join(path, name) + ": expected a number, true or false");
  spec.summary = summarised ? CellSummary::median : CellSummary::none;
  return spec;
}

/// Appends to `out` every leaf of `j` not yet in it, named by its dotted path under `prefix`.
void leaves(const Json& j, const std::string& prefix, std::vector<std::pair<std::string, const Json*>>& out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string name = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object()) leaves(*it, name, out);
    else out.emplace_back(name, &*it);
  }
}

/// The value at dotted `name` in `j`, or null.
const Json* at_path(const Json& j, const std::string& name) {
  const Json* at = &j;
  std::size_t start = 0;
  for (std::size_t dot = name.find('.'); ; dot = name.find('.', start)) {
    const std::string key = name.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!at->is_object()) return nullptr;
    const auto it = at->find(key);
    if (it == at->end()) return nullptr;
    at = &*it;
    if (dot == std::string::npos) return at;
    start = dot + 1;
  }
}

/// The record of a sample: every known run figure in its order (a missing optional one at its
/// fallback, a missing required one an error), then every other figure of the sample in file order.
/// `cell` (the cell object, or null) tells which unknown figures a cell summarises.
FigureRecord sample_figures(const Json& j, const std::string& path, const Json* cell = nullptr) {
  FigureRecord out;
  for (const FigureSpec& spec : run_figure_specs()) {
    const std::size_t dot = spec.name.rfind('.');
    const std::string parent = dot == std::string::npos ? "" : spec.name.substr(0, dot);
    const std::string key = dot == std::string::npos ? spec.name : spec.name.substr(dot + 1);
    const Json* holder = parent.empty() ? &j : at_path(j, parent);
    if (holder == nullptr) at(j, parent, path);  // throws "parent: missing"
    if (!spec.required && !holder->contains(key)) {
      out.add(spec, spec.fallback);
      continue;
    }
    out.add(spec, figure_value(*holder, key, spec, (parent.empty() ? path : join(path, parent))));
  }
  std::vector<std::pair<std::string, const Json*>> all;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (typed_sample_key(it.key())) continue;
    if (it->is_object()) leaves(*it, it.key(), all);
    else all.emplace_back(it.key(), &*it);
  }
  for (const auto& [name, v] : all) {
    if (out.find(name) != nullptr) continue;
    const bool summarised = cell != nullptr && at_path(*cell, name) != nullptr;
    const FigureSpec spec = unknown_figure(name, *v, summarised, path);  // throws unless a number or flag
    out.add(spec, v->is_boolean() ? (v->get<bool>() ? 1.0 : 0.0) : v->get<double>());
  }
  return out;
}

GridSample sample(const Json& j, const std::string& path, const Json* cell) {
  GridSample s;
  s.seed = seed_value(j, "seed", path);
  s.frame_ms = numbers(j, "frame_ms", path);
  s.event_ms = number(j, "event_ms", path);
  s.event_frame = static_cast<int>(integer(j, "event_frame", path));
  s.worst_frame_ms = number(j, "worst_frame_ms", path);
  s.stages_ms = stages(j, "stages_ms", path);
  s.frame_stages_ms = frame_stages(j, s.frame_ms.size(), path);
  s.setup_ms = stages(j, "setup_ms", path);
  const Json& cpu = at(j, "cpu", path);
  s.worst_frame_cpu_ms = number(cpu, "worst_frame_ms", join(path, "cpu"));
  s.stages_cpu_ms = stages(cpu, "stages_ms", join(path, "cpu"));
  s.calibration_ms = number(j, "calibration_ms", path);
  s.figures = sample_figures(j, path, cell);
  if (j.contains("instructions")) s.instructions = instructions(j.at("instructions"), join(path, "instructions"));
  return s;
}

GridCell cell(const Json& j, const std::string& path, double latency_budget_ms) {
  GridCell c;
  c.prefracture = static_cast<int>(integer(j, "prefracture", path));
  c.runtime = static_cast<int>(integer(j, "runtime", path));
  c.prefracturer = text(j, "prefracturer", path);
  c.fracturer = text(j, "fracturer", path);
  c.stress = text(j, "stress", path);
  if (j.contains("failed")) {  // a cell that timed out or crashed: settings and reason only
    c.failed = text(j, "failed", path);
    if (c.failed.empty()) throw BadKey(join(path, "failed") + ": expected the reason the cell failed");
    if (j.contains("schedule")) c.schedule = text(j, "schedule", path);
    c.within_budget = false;
    c.within_latency_budget = false;
    return c;
  }
  c.worst_frame_ms = number(j, "worst_frame_ms", path);
  const Json& f = at(j, "frame_ms", path);
  const std::string fp = join(path, "frame_ms");
  c.frame_ms.mean = number(f, "mean", fp);
  c.frame_ms.median = number(f, "median", fp);
  c.frame_ms.p95 = number(f, "p95", fp);
  c.frame_ms.p99 = number(f, "p99", fp);
  c.frame_ms.max = number(f, "max", fp);
  c.frame_ms.min = number(f, "min", fp);
  c.event_ms = number(j, "event_ms", path);
  c.stages_ms = stages(j, "stages_ms", path);
  c.setup_ms = stages(j, "setup_ms", path);
  const Json& e = at(j, "error", path);
  const std::string ep = join(path, "error");
  const Json& pre = at(e, "prefracture", ep);
  const Json& run = at(e, "runtime", ep);
  const Json& st = at(e, "stress", ep);
  c.accuracy.prefracture_volume_error = number(pre, "volume_error", ep + ".prefracture");
  c.accuracy.prefracture_partition_error = number(pre, "partition_error", ep + ".prefracture");
  c.accuracy.prefracture_all_closed = boolean(pre, "all_closed", ep + ".prefracture");
  c.accuracy.prefracture_min_fragment_volume = number(pre, "min_fragment_volume", ep + ".prefracture");
  c.accuracy.runtime_volume_error = number(run, "volume_error", ep + ".runtime");
  c.accuracy.runtime_partition_error = number(run, "partition_error", ep + ".runtime");
  c.accuracy.runtime_all_closed = boolean(run, "all_closed", ep + ".runtime");
  c.accuracy.runtime_min_fragment_volume = number(run, "min_fragment_volume", ep + ".runtime");
  c.accuracy.solver_converged = boolean(st, "converged", ep + ".stress");
  c.accuracy.solver_residual = number(st, "residual", ep + ".stress");
  c.within_budget = boolean(j, "within_budget", path);
  for (const Json& name : array(j, "stages_run", path)) {
    if (!name.is_string()) throw BadKey(join(path, "stages_run") + ": expected strings");
    c.stages_run.push_back(name.get<std::string>());
  }
  const Json& skipped = array(j, "stages_skipped", path);
  for (std::size_t i = 0; i < skipped.size(); ++i) {
    const std::string sp = fmt::format("{}.stages_skipped[{}]", path, i);
    c.stages_skipped.push_back({text(skipped[i], "stage", sp), text(skipped[i], "reason", sp)});
  }
  const Json& samples = array(j, "samples", path);
  for (std::size_t i = 0; i < samples.size(); ++i)
    c.samples.push_back(sample(samples[i], fmt::format("{}.samples[{}]", path, i), &j));
  if (c.samples.empty()) throw BadKey(join(path, "samples") + ": no samples");
  // Summaries as written; a file from before a summarised figure has it recomputed from the samples.
  summarise_cell_figures(c, latency_budget_ms);
  if (j.contains("schedule")) c.schedule = text(j, "schedule", path);
  FigureRecord summaries;
  for (const Figure& fig : c.summaries.figures()) {
    const std::size_t dot = fig.spec.name.rfind('.');
    const std::string parent = dot == std::string::npos ? "" : fig.spec.name.substr(0, dot);
    const std::string key = dot == std::string::npos ? fig.spec.name : fig.spec.name.substr(dot + 1);
    const Json* holder = parent.empty() ? &j : at_path(j, parent);
    const bool written = holder != nullptr && holder->is_object() && holder->contains(key);
    summaries.add(fig.spec, written ? figure_value(*holder, key, fig.spec, (parent.empty() ? path : join(path, parent))) : fig.value);
  }
  c.summaries = std::move(summaries);
  if (j.contains("within_latency_budget")) c.within_latency_budget = boolean(j, "within_latency_budget", path);
  return c;
}

}  // namespace

Result<GridCell> grid_cell_from_json(const nlohmann::ordered_json& j, const std::string& what,
                                     double latency_budget_ms) {
  try {
    return cell(j, "", latency_budget_ms);
  } catch (const BadKey& e) {
    return Error{what + ": " + e.what()};
  }
}

Result<StoredGrid> grid_results_from_json(const nlohmann::ordered_json& j, const std::string& what) {
  if (const std::optional<std::string> key = first_non_finite(j))
    return Error{what + ": " + *key + ": a number that is not finite (too large for a double)"};
  try {
    StoredGrid out;
    const long long version = integer(j, "schema_version", "");
    if (version != kGridSchemaVersion)
      return Error{fmt::format("{}: schema_version: {} is not supported (this build reads {})", what, version,
                               kGridSchemaVersion)};
    Result<RunContext> context = context_from_json(nlohmann::json(at(j, "context", "")));
    if (!context) return Error{what + ": " + context.error().message};
    out.context = std::move(*context);
    out.case_block = at(j, "case", "");
    out.case_name = text(out.case_block, "name", "case");
    if (j.contains("input")) out.input_block = j.at("input");
    if (j.contains("recorded_frames")) {
      out.recorded_frames_block = j.at("recorded_frames");
      (void)text(out.recorded_frames_block, "path", "recorded_frames");  // throws unless a name is there
    }
    if (j.contains("metric")) out.metric = text(j, "metric", "");
    if (out.metric != "time" && out.metric != "instructions")
      return Error{what + ": metric: expected \"time\" or \"instructions\", got \"" + out.metric + "\""};
    out.grid.budget_ms = number(j, "budget_ms", "");
    if (j.contains("latency_budget_ms")) out.grid.latency_budget_ms = number(j, "latency_budget_ms", "");
    out.grid.repetitions = static_cast<int>(integer(j, "repetitions", ""));
    out.grid.frames = static_cast<int>(integer(j, "frames", ""));
    out.grid.no_skip = boolean(j, "no_skip", "");
    out.grid.same_seed = boolean(j, "same_seed", "");
    // Files written before worker threads ran every event on one thread.
    if (j.contains("threads")) out.grid.threads = static_cast<int>(integer(j, "threads", ""));
    out.grid.wall_s = number(j, "wall_s", "");
    if (j.contains("cell_timeout_s")) out.grid.cell_timeout_s = number(j, "cell_timeout_s", "");
    if (j.contains("shard")) {
      out.grid.shard_index = static_cast<int>(integer(j.at("shard"), "index", "shard"));
      out.grid.shard_count = static_cast<int>(integer(j.at("shard"), "count", "shard"));
    }
    const Json& cells = array(j, "cells", "");
    for (std::size_t i = 0; i < cells.size(); ++i) out.grid.cells.push_back(cell(cells[i], fmt::format("cells[{}]", i), out.grid.latency_budget_ms));
    return out;
  } catch (const BadKey& e) {
    return Error{what + ": " + e.what()};
  }
}

Result<StoredGrid> read_grid_results(const std::filesystem::path& path) {
  const Result<std::string> text = read_file_bounded(path, kMaxResultsFileBytes, "results file");
  if (!text) return text.error();
  Result<Json> j = parse_results_json(*text, path.string());
  if (!j) return j.error();
  Result<StoredGrid> out = grid_results_from_json(*j, path.string());
  if (out) out->path = path;
  return out;
}

}  // namespace shatter
