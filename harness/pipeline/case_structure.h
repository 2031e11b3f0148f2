#pragma once
/// A case's structure before any impact: the solid, its pre-fracture and the support graph, built by the
/// same offline setup as a destruction run (setup/offline_structure.h) at the case's own settings.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/registry/registries.h"
#include "harness/cases/case.h"
#include "harness/cases/load_solid.h"

#include <vector>

namespace shatter {

/// The pre-fractured structure of a case.
struct CaseStructure {
  Solid solid;                       ///< the validated input solid
  std::vector<Fragment> fragments;   ///< pre-fracture fragments
  SupportGraph graph;                ///< bonds between the fragments, anchors from the case
};

/// The whole structure of `c`: its solid pre-fractured (explicit planes cut by their plane_cutter, or
/// the case's fracturer, count and seed; no cache) and its support graph at the case's density. Errors
/// name the case key: an unknown fracturer (`prefracture.fracturer`), an anchor region that touches no
/// fragment (`anchors[i]`), or a setting the fracturer refuses. The fracturer comes from `registries`,
/// with the case's `prefracture.settings`.
Result<CaseStructure> build_case_structure(const Case& c, const Registries& registries);

}  // namespace shatter
