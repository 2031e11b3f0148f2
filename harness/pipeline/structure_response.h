#pragma once
/// How the standing structure answers a change: the stress solve that breaks what now fails (until
/// stable), and the standing components that lost every anchor. Used by the setup (the structure under
/// its own weight) and by the runtime event (after the hit fragments' bonds are removed).

#include "algorithms/core/result.h"
#include "harness/pipeline/run_state.h"

#include <vector>

namespace shatter {

/// Solves the stress of `run`'s structure under its loads, breaking bonds (RunResult::broken) until
/// stable; times the stage into `clocks` and adds the rounds and solver figures to the result. Skipped,
/// with the reason recorded, when stress is not needed, or (with skips on, for a load-driven model)
/// without gravity or anchors. `after_hit`: the solve follows an impact (its partial re-solves are
/// recorded as a skip). Errors name the case and `stress`.
Status solve_structure_stress(RunState& run, bool after_hit, StageClocks& clocks);

/// Union-find over the intact bonds between standing fragments: the standing components that have
/// lost every anchor. Each cluster ascending; clusters in order of their smallest fragment; none
/// without bonds.
std::vector<std::vector<int>> newly_falling_clusters(const RunState& run);

}  // namespace shatter
