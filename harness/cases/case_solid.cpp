// The case's solid: its mesh made a solid by make_solid (repaired unless the case refuses repair). In a
// unit of its own so that what reads cases without making solids (the case loader's fuzz target) does
// not link mesh repair (CGAL).

#include "harness/cases/case_mesh.h"

#include "algorithms/core/surface_mapping.h"

#include <fmt/format.h>

#include <string>
#include <utility>
#include <variant>

namespace shatter {

void refuse_repair(Case& c) {
  if (auto* file = std::get_if<MeshFileSpec>(&c.mesh)) file->repair = false;
}

void set_cap_uv_scale(Case& c, double metres_per_uv) { c.appearance.cap_uv_scale = metres_per_uv; }

Result<Solid> build_case_solid(const Case& c) {
  const std::string what = fmt::format("{}: mesh", c.source.empty() ? c.name : c.source.string());
  Result<Mesh> mesh = build_case_mesh(c.mesh, what);
  if (!mesh) return mesh.error();
  const AppearanceSpec& look = c.appearance;
  if (look.surface) apply_box_mapping(*mesh, look.uv_scale, *look.surface);
  const std::string name = std::holds_alternative<MeshFileSpec>(c.mesh)
                               ? fmt::format("{} ({})", what, std::get<MeshFileSpec>(c.mesh).path.string())
                               : what;
  const SolidRepair repair = std::holds_alternative<MeshFileSpec>(c.mesh) && !std::get<MeshFileSpec>(c.mesh).repair
                                 ? SolidRepair::refuse
                                 : SolidRepair::repair;
  return make_solid(std::move(mesh).value(), name, repair, CutFaceOptions{look.cap_uv_scale, look.interior});
}

}  // namespace shatter
