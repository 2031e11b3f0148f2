#pragma once
/// The `mesh` of a case: reading its JSON description (a primitive or a transformed mesh file) and
/// building the validated solid from it.

#include "harness/cases/case.h"
#include "harness/cases/json_reader.h"
#include "harness/cases/load_solid.h"

#include <filesystem>

namespace shatter {

/// Reads the mesh description `value` found at key path `path`. A relative `file` is resolved
/// against `case_dir` first, then the current directory, and must exist. Errors go to `reader`; a
/// primitive past the limits of harness/limits.h (segments, triangles, prism corners) is one.
MeshSpec read_mesh_spec(JsonReader& reader, const nlohmann::json& value, std::string_view path,
                        const std::filesystem::path& case_dir);

/// Builds the (not yet validated) mesh a spec describes; a file that cannot be read is an error
/// naming it. `what` prefixes errors (for example "cases/x.json: mesh").
Result<Mesh> build_case_mesh(const MeshSpec& spec, const std::string& what);

/// Builds and validates the case's solid (closed, oriented, positive volume), dressed as its
/// `appearance` says, and measures it. Errors name the case file and the mesh.
Result<Solid> build_case_solid(const Case& c);

/// Makes the case refuse a mesh file that is not a solid instead of repairing it (`--no-repair`).
void refuse_repair(Case& c);

/// Sets the case's cut-face UV scale (`--cap-uv-scale`, metres per UV unit, > 0), overriding its
/// `appearance.cap_uv_scale`.
void set_cap_uv_scale(Case& c, double metres_per_uv);

/// Rotation matrix of `degrees` about x, then y, then z; multiples of 90 degrees are exact.
Eigen::Matrix3d rotation_xyz_deg(const Vec3& degrees);

}  // namespace shatter
