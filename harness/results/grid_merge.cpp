#include "harness/results/grid_merge.h"

#include <fmt/core.h>

#include <algorithm>
#include <set>
#include <tuple>

namespace shatter {

Result<StoredGrid> merge_grids(const std::vector<StoredGrid>& parts) {
  if (parts.empty()) return Error{"merge: no results to merge"};
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
    if (p.grid.repetitions != first.grid.repetitions) return differs("repetitions");
    if (p.grid.frames != first.grid.frames) return differs("frames");
    if (p.grid.no_skip != first.grid.no_skip) return differs("no_skip");
    if (p.grid.same_seed != first.grid.same_seed) return differs("same_seed");
    if (p.grid.cell_timeout_s != first.grid.cell_timeout_s) return differs("cell_timeout_s");
    for (const GridCell& c : p.grid.cells) {
      if (!seen.emplace(c.prefracture, c.runtime, c.prefracturer, c.fracturer, c.stress).second)
        return Error{fmt::format("merge: cell {} x {} appears twice (again in {})", c.prefracture, c.runtime, name)};
      out.grid.cells.push_back(c);
    }
    out.grid.wall_s += p.grid.wall_s;
  }
  std::stable_sort(out.grid.cells.begin(), out.grid.cells.end(), [](const GridCell& a, const GridCell& b) {
    return std::tie(a.prefracture, a.runtime) < std::tie(b.prefracture, b.runtime);
  });
  return out;
}

}  // namespace shatter
