#pragma once
/// The offline setup of a case's structure, written once for every user: the destruction run, the
/// `stress` command and the stress accuracy runs. Pre-fracture (explicit planes cut by a fracturer that
/// cuts by given planes, or a fracturer's own fracture; through the cache when one is given), the anchor regions, the support graph.
/// Each part is timed in the setup clocks and recorded in the stage log (docs/pipeline.md section 1).

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "harness/cases/case.h"
#include "harness/cases/load_solid.h"
#include "harness/pipeline/prefracture_cache.h"
#include "harness/pipeline/stage.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shatter {

/// How the offline setup pre-fractures a case's solid and what it builds after.
struct OfflineSetupRequest {
  /// Pre-fracture algorithm, never null; for explicit planes one that cuts by given planes
  /// (Fracturer::plane_cutting: plane_cutter, harness/plugins/capable_fracturer.h).
  const Fracturer* fracturer = nullptr;
  std::string settings;                      ///< settings_text of its settings ("" for none), part of the cache key
  int fragments = 0;                         ///< requested fragment count (ignored for explicit planes)
  std::uint64_t seed = 0;                    ///< pre-fracture seed (ignored for explicit planes)
  const PrefractureCache* cache = nullptr;   ///< cache to read and fill, or none
  bool read_cache = true;                    ///< false: recompute a cached pre-fracture (and store it again)
  bool bonds = true;                         ///< build the support graph (false: stage `bonds` skipped)
};

/// A case's structure after the offline setup.
struct OfflineStructure {
  std::vector<Fragment> fragments;           ///< the pre-fracture
  std::vector<std::uint8_t> anchored;        ///< per fragment: 1 when it overlaps an anchor region
  SupportGraph graph;                        ///< bonds and anchors (empty when bonds were not requested)
  PrefractureKey key;                        ///< what was fractured (count and seed 0 for explicit planes)
  bool cache_hit = false;                    ///< the pre-fracture came from the cache
};

/// Pre-fractures `solid` of case `c` as `request` says, checks the anchor regions and builds the support
/// graph at the case's density. Stage times go to `setup`, ran and skipped stages to `stages`. Errors
/// name the case key: `prefracture.planes`, `prefracture` (a failed fracture), `anchors[i]` (a region
/// that touches no fragment), or the support graph's message.
Result<OfflineStructure> build_offline_structure(const Case& c, const Solid& solid, const OfflineSetupRequest& request,
                                                 StageClocks& setup, StageLog& stages);

}  // namespace shatter
