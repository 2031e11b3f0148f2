#include "harness/results/grid_merge.h"

#include "harness/results/cell_summary.h"
#include "harness/results/grid_json_reporter.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <map>
#include <string>
#include <set>
#include <tuple>

namespace shatter {

namespace {

using CellKey = std::tuple<int, int, std::string, std::string, std::string>;

CellKey key_of(const GridCell& c) { return {c.prefracture, c.runtime, c.prefracturer, c.fracturer, c.stress}; }

std::string cell_name(const GridCell& c) { return fmt::format("{} x {}", c.prefracture, c.runtime); }

/// Joins the samples of each cell of `parts` (checked alike but for repetitions) into `out`.
Result<StoredGrid> join_repetitions(const std::vector<StoredGrid>& parts, StoredGrid out) {
  std::map<CellKey, std::size_t> index;
  for (std::size_t i = 0; i < out.grid.cells.size(); ++i)
    if (!index.emplace(key_of(out.grid.cells[i]), i).second)
      return Error{fmt::format("merge: cell {} appears twice in {}", cell_name(out.grid.cells[i]), out.path.string())};
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const StoredGrid& p = parts[k];
    if (p.grid.cells.size() != out.grid.cells.size())
      return Error{fmt::format("merge: {} has {} cells, {} has {}: repetitions must hold the same cells",
                               p.path.string(), p.grid.cells.size(), parts.front().path.string(),
                               out.grid.cells.size())};
    for (const GridCell& c : p.grid.cells) {
      const auto it = index.find(key_of(c));
      if (it == index.end())
        return Error{fmt::format("merge: cell {} of {} is not in {}", cell_name(c), p.path.string(),
                                 parts.front().path.string())};
      GridCell& into = out.grid.cells[it->second];
      if (c.schedule != into.schedule)
        return Error{fmt::format("merge: {} differs from {} in the schedule of cell {}", p.path.string(),
                                 parts.front().path.string(), cell_name(c))};
      if (!c.failed.empty() && into.failed.empty()) into.failed = c.failed;  // failed in one run: failed
      into.samples.insert(into.samples.end(), c.samples.begin(), c.samples.end());
      add_cell_accuracy(into.accuracy, c.accuracy);
      add_cell_stages(into, c.stages_run, c.stages_skipped);
    }
    out.grid.repetitions += p.grid.repetitions;
    out.grid.wall_s += p.grid.wall_s;
  }
  for (GridCell& c : out.grid.cells) {
    if (c.failed.empty()) {
      summarise_cell(c, out.grid.budget_ms, out.grid.latency_budget_ms);
    } else {  // as a failed cell reports: its settings and the reason, no samples
      GridCell bare;
      bare.prefracture = c.prefracture;
      bare.runtime = c.runtime;
      bare.prefracturer = c.prefracturer;
      bare.fracturer = c.fracturer;
      bare.stress = c.stress;
      bare.schedule = c.schedule;
      bare.failed = c.failed;
      bare.within_budget = bare.within_latency_budget = false;
      c = std::move(bare);
    }
  }
  return out;
}

/// True when `a` and `b` name one file: the same path once resolved, or the same device and inode
/// (a hard link, a symbolic link, a bind mount).
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec) && !ec) return true;
  const auto ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ec), ec);
  const auto cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, ec), ec);
  return !ec && ca == cb;
}

/// True when `a` and `b` hold one run: the same context (commit, machine, date, ...) and every cell
/// with the same samples. Two runs never time every frame alike, so this is a copy of one run.
bool same_run(const StoredGrid& a, const StoredGrid& b) {
  if (to_json(a.context) != to_json(b.context) || a.grid.cells.size() != b.grid.cells.size()) return false;
  for (std::size_t i = 0; i < a.grid.cells.size(); ++i)
    if (grid_cell_to_json(a.grid.cells[i]) != grid_cell_to_json(b.grid.cells[i])) return false;
  return true;
}

/// Error when two parts are one file or one run: merged, one run would count twice (its samples as
/// new repetitions, narrowing the spread the U test sees).
Status check_distinct_parts(const std::vector<StoredGrid>& parts) {
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t k = i + 1; k < parts.size(); ++k) {
      const std::string a = parts[i].path.string(), b = parts[k].path.string();
      if (same_file(parts[i].path, parts[k].path))
        return Error{fmt::format("merge: {} and {} are the same file: each run is merged once", a, b)};
      if (same_run(parts[i], parts[k]))
        return Error{fmt::format("merge: {} and {} hold the same run (same context and samples): each run is merged once",
                                 a, b)};
    }
  return {};
}

}  // namespace

Result<StoredGrid> merge_grids(const std::vector<StoredGrid>& parts, MergeParts kind) {
  if (parts.empty()) return Error{"merge: no results to merge"};
  if (Status s = check_distinct_parts(parts); !s) return s.error();
  const StoredGrid& first = parts.front();
  StoredGrid out = first;
  out.grid.cells.clear();
  out.grid.wall_s = 0.0;
  out.grid.shard_index = 0;
  out.grid.shard_count = 1;
  std::set<std::tuple<int, int, std::string, std::string, std::string>> seen;
  for (const StoredGrid& p : parts) {
    const std::string name = p.path.string();
    const auto differs = [&](const std::string& what) {
      return Error{fmt::format("merge: {} differs from {} in {}", name, first.path.string(), what)};
    };
    if (p.context.fingerprint != first.context.fingerprint) return differs("the build fingerprint");
    if (p.context.commit != first.context.commit) return differs("the commit");
    if (p.case_block != first.case_block) return differs("the case");
    if (p.metric != first.metric) return differs("the metric");
    if (p.grid.budget_ms != first.grid.budget_ms) return differs("budget_ms");
    if (kind == MergeParts::shards && p.grid.repetitions != first.grid.repetitions) return differs("repetitions");
    if (p.grid.latency_budget_ms != first.grid.latency_budget_ms) return differs("latency_budget_ms");
    if (p.grid.frames != first.grid.frames) return differs("frames");
    if (p.grid.no_skip != first.grid.no_skip) return differs("no_skip");
    if (p.grid.same_seed != first.grid.same_seed) return differs("same_seed");
    if (p.grid.threads != first.grid.threads) return differs("threads");
    if (p.grid.cell_timeout_s != first.grid.cell_timeout_s) return differs("cell_timeout_s");
    if (kind == MergeParts::repetitions) continue;
    for (const GridCell& c : p.grid.cells) {
      if (!seen.emplace(c.prefracture, c.runtime, c.prefracturer, c.fracturer, c.stress).second)
        return Error{fmt::format("merge: cell {} x {} appears twice (again in {})", c.prefracture, c.runtime, name)};
      out.grid.cells.push_back(c);
    }
    out.grid.wall_s += p.grid.wall_s;
  }
  if (kind == MergeParts::repetitions) {
    out.grid.cells = first.grid.cells;
    out.grid.wall_s = first.grid.wall_s;
    return join_repetitions(parts, std::move(out));
  }
  std::stable_sort(out.grid.cells.begin(), out.grid.cells.end(), [](const GridCell& a, const GridCell& b) {
    return std::tie(a.prefracture, a.runtime) < std::tie(b.prefracture, b.runtime);
  });
  return out;
}

}  // namespace shatter
