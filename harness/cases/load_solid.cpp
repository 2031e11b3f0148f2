#include "harness/cases/load_solid.h"

#include "algorithms/assets/read_asset.h"
#include "harness/cases/isolated_import.h"
#include "harness/cases/isolated_repair.h"
#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/representable_range.h"

#include <utility>

namespace shatter {
namespace {

/// The mesh as the acceptance rule leaves it, and what the rule normalised; or the rule's reason.
Result<std::pair<Mesh, ValidationReport>> accepted(Mesh mesh, const std::string& what) {
  Result<ValidationReport> report = validate_solid(mesh, what);
  if (!report) return report.error();
  return std::pair{std::move(mesh), *report};
}

}  // namespace

Result<Solid> make_solid(Mesh mesh, const std::string& what, SolidRepair repair, const CutFaceOptions& cut) {
  // Before anything measures the mesh: the mass properties of a mesh past the range overflow.
  if (Status s = check_representable(mesh, what); !s) return s.error();
  Solid solid;
  auto as_given = accepted(mesh, what);
  if (!as_given) {
    if (repair == SolidRepair::refuse) return as_given.error();
    Result<RepairedSolid> repaired =
        repair == SolidRepair::repair_in_process ? repair_solid(mesh, what) : repair_solid_isolated(mesh, what);
    if (!repaired) return repaired.error();
    solid.repair = repaired->report;
    transfer_attributes(mesh, repaired->mesh);
    as_given = accepted(std::move(repaired->mesh), what + " (repaired)");
    if (!as_given) return as_given.error();
  }
  solid.mesh = std::move(as_given->first);
  solid.report = as_given->second;
  prepare_cut_faces(solid.mesh, cut.uv_scale, cut.interior ? &*cut.interior : nullptr);
  if (Status s = check_attributes(solid.mesh, what); !s) return s.error();
  solid.mass = mass_properties(solid.mesh);
  solid.area = surface_area(solid.mesh);
  return solid;
}

Result<Solid> load_solid(const std::filesystem::path& path, SolidRepair repair, const CutFaceOptions& cut) {
  Result<Mesh> mesh = read_asset_isolated(path);
  if (!mesh) return mesh.error();
  return make_solid(std::move(*mesh), path.string(), repair, cut);
}

}  // namespace shatter
