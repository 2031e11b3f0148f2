#pragma once
/// Reading a solid from a mesh file for the harness: read, repair when needed, validate, measure.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/result.h"
#include "algorithms/repair/repair_solid.h"

#include <filesystem>
#include <optional>
#include <string>

namespace shatter {

/// What to do with a mesh that is not a solid.
enum class SolidRepair {
  repair,             ///< repair it in a child under the repair budget (isolated_repair.h); refuse it only when no solid exists
  refuse,             ///< refuse it with the acceptance rule's reason (`--no-repair`)
  repair_in_process,  ///< repair it in this process, without a budget: for the repair fuzzer, which must see a crash
};

/// How a solid's cut faces are dressed when it carries attributes (attribute_transfer.h).
struct CutFaceOptions {
  double uv_scale = 0.0;                 ///< metres per UV unit on cut faces; 0: the default
  std::optional<MaterialSlot> interior;  ///< the interior material; none: "interior", mid grey
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
/// `repair`, validates it as a solid and measures it. Errors name the file. `cut` as for make_solid.
Result<Solid> load_solid(const std::filesystem::path& path, SolidRepair repair = SolidRepair::repair,
                         const CutFaceOptions& cut = {});

/// Repairs (per `repair`), validates and measures an in-memory mesh; `what` names it in errors. Every
/// input solid of the harness (mesh files and case meshes alike) passes here: a mesh outside the
/// representable range (representable_range.h) is refused before it is measured. A mesh that passes
/// the acceptance rule (validate_solid) is never repaired; one that fails it is repaired, and the
/// repaired mesh must pass the rule in turn.
///
/// A mesh with attributes (normals, UVs, tangents, materials) keeps them: a repaired mesh gets them
/// by transfer_attributes (attribute_transfer.h: surface faces from the input triangle they lie on,
/// faces repair added dressed by the planar rule in the material around them); then
/// prepare_cut_faces adds `cut`'s interior material and sets its cut-face UV scale (0 takes the
/// default, the largest side of the solid's box). Attributes that are not finite are refused with the
/// triangle named.
Result<Solid> make_solid(Mesh mesh, const std::string& what, SolidRepair repair = SolidRepair::repair,
                         const CutFaceOptions& cut = {});

}  // namespace shatter
