#pragma once
/// The offline part of a destruction run, before frame 0 (docs/pipeline.md section 1): the algorithms
/// named by the case and the options, the shared offline structure (setup/offline_structure.h), the
/// structure settled under its own weight, and the physics world with the standing fragments as static
/// bodies. Timed per stage in RunResult::setup; a game does it while loading, so it is not a frame.

#include "algorithms/core/result.h"
#include "harness/pipeline/run_state.h"

namespace shatter {

/// Creates the run's pre-fracture and runtime fracturers and its stress model (options first, else the
/// case's names) and takes the runtime count and the loads. Errors name the case key of the unknown
/// name (`prefracture.fracturer`, `runtime.fracturer`, `stress.model`).
Status create_run_algorithms(RunState& run);

/// The whole offline setup of `run` (create_run_algorithms first): pre-fracture (with the cache unless
/// skips are off) and its error figures, anchors and bonds, the first stress solve and the clusters
/// that fall at once, and the physics world. Errors name what failed.
Status run_setup(RunState& run);

}  // namespace shatter
