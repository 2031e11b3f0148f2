#pragma once
/// Joining the shards of one grid (`grid --shard K/N` on several runners) into one results file.

#include "algorithms/core/result.h"
#include "harness/results/grid_reader.h"

#include <vector>

namespace shatter {

/// What the parts of a merge are.
enum class MergeParts {
  shards,       ///< disjoint sets of cells of one grid (`grid --shard K/N`)
  repetitions,  ///< the same cells run again (interleaved runs of two builds, docs/compare.md)
};

/// Merges `parts` into one grid: every part must come from the same build and commit (fingerprint and
/// commit), the same case, budget, frames, skip mode, seed mode and metric. Shards must also agree on
/// the repetitions, and no cell may appear twice; cells come out in (pre-fracture, runtime) order.
/// Repetitions must hold the same cells, whose samples are joined in the order of the parts, the
/// summaries recomputed from them and the error figures the worst of the parts; `repetitions` is the
/// sum. The context is the first part's; `wall_s` is the sum. Errors name the part and what differs.
Result<StoredGrid> merge_grids(const std::vector<StoredGrid>& parts, MergeParts kind = MergeParts::shards);

}  // namespace shatter
