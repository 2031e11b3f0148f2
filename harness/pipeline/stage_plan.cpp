#include "harness/pipeline/stage_plan.h"

namespace shatter {

StagePlan plan_for(const Needs& needs) {
  StagePlan p;
  p.physics = needs.physics;
  p.colliders = needs.colliders || needs.physics;
  p.stress = needs.stress;
  p.bonds = needs.bonds || needs.stress;
  p.fragments = true;  // every other stage works on fragments
  return p;
}

}  // namespace shatter
