#include "harness/cases/load_solid.h"

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/representable_range.h"

namespace shatter {

Result<Solid> make_solid(Mesh mesh, const std::string& what) {
  // Before anything measures the mesh: the mass properties of a mesh past the range overflow.
  if (Status s = check_representable(mesh, what); !s) return s.error();
  Result<ValidationReport> report = validate_solid(mesh, what);
  if (!report) return report.error();
  Solid solid;
  solid.mass = mass_properties(mesh);
  solid.area = surface_area(mesh);
  solid.mesh = std::move(mesh);
  solid.report = *report;
  return solid;
}

Result<Solid> load_solid(const std::filesystem::path& path) {
  Result<Mesh> mesh = read_mesh(path);
  if (!mesh) return mesh.error();
  return make_solid(std::move(*mesh), path.string());
}

}  // namespace shatter
