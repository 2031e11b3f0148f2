#pragma once
/// Reading a solid from a mesh file for the harness: read, validate, measure.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/result.h"

#include <filesystem>

namespace shatter {

/// A validated input solid.
struct Solid {
  Mesh mesh;                  ///< closed, outward
  MassProperties mass;        ///< of `mesh`, density 1
  double area = 0.0;          ///< surface area, m^2
  ValidationReport report;    ///< what validation fixed
};

/// Reads `path` (.off or .obj), validates it as a solid and measures it. Errors name the file.
Result<Solid> load_solid(const std::filesystem::path& path);

/// Validates and measures an in-memory mesh; `what` names it in errors. Every input solid of the
/// harness (mesh files and case meshes alike) passes here: a mesh outside the representable range
/// (representable_range.h) is refused before it is measured.
Result<Solid> make_solid(Mesh mesh, const std::string& what);

}  // namespace shatter
