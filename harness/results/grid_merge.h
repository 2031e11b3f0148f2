#pragma once
/// Joining the shards of one grid (`grid --shard K/N` on several runners) into one results file.

#include "algorithms/core/result.h"
#include "harness/results/grid_reader.h"

#include <vector>

namespace shatter {

/// Merges `parts` into one grid: every part must come from the same build and commit (fingerprint and
/// commit), the same case, budget, repetitions, frames, skip mode and metric; no cell may appear
/// twice. Cells come out in (pre-fracture, runtime) order; the context is the first part's; `wall_s`
/// is the sum. Errors name the part and what differs.
Result<StoredGrid> merge_grids(const std::vector<StoredGrid>& parts);

}  // namespace shatter
