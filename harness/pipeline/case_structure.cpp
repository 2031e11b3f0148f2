#include "harness/pipeline/case_structure.h"

#include "algorithms/registry/register_all.h"
#include "harness/cases/case_mesh.h"
#include "harness/pipeline/setup/offline_structure.h"

#include <memory>
#include <utility>

namespace shatter {

Result<CaseStructure> build_case_structure(const Case& c) {
  Result<Solid> solid = build_case_solid(c);
  if (!solid) return solid.error();
  std::unique_ptr<Fracturer> fracturer;
  if (!c.prefracture.explicit_planes()) {
    auto created = registries().fracturers.create(c.prefracture.fracturer);
    if (!created) return Error{c.name + ": prefracture.fracturer: " + created.error().message};
    fracturer = std::move(*created);
  }
  OfflineSetupRequest request;
  request.fracturer = fracturer.get();
  request.fragments = c.prefracture.fragments;
  request.seed = c.prefracture.seed;
  StageClocks untimed;
  StageLog untracked;
  Result<OfflineStructure> structure = build_offline_structure(c, *solid, request, untimed, untracked);
  if (!structure) return structure.error();

  CaseStructure out;
  out.solid = std::move(*solid);
  out.fragments = std::move(structure->fragments);
  out.graph = std::move(structure->graph);
  return out;
}

}  // namespace shatter
