#pragma once
/// The stages a case's needs imply (docs/pipeline.md section 2): physics needs colliders, stress needs
/// bonds, and every stage works on fragments.

#include "harness/cases/case.h"

namespace shatter {

/// Which stages of a destruction run are wanted; a stage that is not is skipped with the reason
/// "not needed (case needs)".
struct StagePlan {
  bool fragments = true;  ///< pre-fracture and runtime fracture (always)
  bool bonds = true;      ///< the support graph (bonds or stress needed)
  bool stress = true;     ///< the stress solve and propagation
  bool colliders = true;  ///< the physics world's bodies (colliders or physics needed)
  bool physics = true;    ///< the physics steps
};

/// The plan for `needs`: each need together with the needs it implies.
StagePlan plan_for(const Needs& needs);

}  // namespace shatter
