#include "harness/pipeline/case_structure.h"

#include "harness/cases/case_mesh.h"
#include "harness/pipeline/setup/offline_structure.h"
#include "harness/plugins/capable_fracturer.h"

#include <memory>
#include <utility>

namespace shatter {

Result<CaseStructure> build_case_structure(const Case& c, const Registries& registries) {
  Result<Solid> solid = build_case_solid(c);
  if (!solid) return solid.error();
  std::unique_ptr<Fracturer> fracturer;
  if (c.prefracture.explicit_planes()) {
    auto cutter = plane_cutter(registries.fracturers, c.prefracture.fracturer, c.prefracture.settings);
    if (!cutter) return Error{c.name + ": prefracture.planes: " + cutter.error().message};
    fracturer = std::move(*cutter);
  } else {
    auto created = registries.fracturers.create(c.prefracture.fracturer, c.prefracture.settings);
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
