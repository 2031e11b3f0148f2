#pragma once
/// Reading a solid from a mesh file for the harness: read, repair when needed, validate, measure.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/result.h"
#include "algorithms/repair/repair_solid.h"

#include <filesystem>
#include <string>

namespace shatter {

/// What to do with a mesh that is not a solid.
enum class SolidRepair {
  repair,  ///< repair it (repair_solid); refuse it only when no solid exists
  refuse,  ///< refuse it with the acceptance rule's reason (`--no-repair`)
};

/// A validated input solid.
struct Solid {
  Mesh mesh;                  ///< closed, outward; faces repair added are tagged FaceTag::repair
  MassProperties mass;        ///< of `mesh`, density 1
  double area = 0.0;          ///< surface area, m^2 (every tag)
  ValidationReport report;    ///< what validation normalised
  RepairReport repair;        ///< what repair changed (all zero when the mesh was a solid)
};

/// Reads `path` (any format read_asset reads: .off, .obj, glTF, FBX, PLY, STL, ...), repairs it per
/// `repair`, validates it as a solid and measures it. Errors name the file.
Result<Solid> load_solid(const std::filesystem::path& path, SolidRepair repair = SolidRepair::repair);

/// Repairs (per `repair`), validates and measures an in-memory mesh; `what` names it in errors. Every
/// input solid of the harness (mesh files and case meshes alike) passes here: a mesh outside the
/// representable range (representable_range.h) is refused before it is measured. A mesh that passes
/// the acceptance rule (validate_solid) is never repaired; one that fails it is repaired, and the
/// repaired mesh must pass the rule in turn. A mesh with attributes is readied for fracture
/// (prepare_cut_faces: the interior material, the default cut-face UV scale).
Result<Solid> make_solid(Mesh mesh, const std::string& what, SolidRepair repair = SolidRepair::repair);

}  // namespace shatter
