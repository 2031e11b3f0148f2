#pragma once
/// cgal-clip: the exact reference. The same cut schedule as plane-slice (recursive_slicing.h), each
/// cut done by CGAL's Polygon_mesh_processing on an exact-constructions kernel; and the exact replay
/// of a cell fracture (Voronoi) from its half-spaces. CGAL stays inside this folder's translation units.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/convex_cell.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/fracturer_registry.h"

#include <cstddef>
#include <span>

namespace shatter {

/// The most fragments, planes or cells the exact reference accepts. Exact constructions make every
/// cut cost far more than plane-slice's (about 8 s for a 1,848-triangle sphere into 100 fragments on
/// a 2-core machine, growing a little faster than the fragment count), so a request past this would
/// run for minutes: it is refused at once with this figure named. The harness compares algorithms
/// against the reference at up to 100 fragments.
inline constexpr int kMaxReferenceFragments = 250;

/// Error "cgal-clip: at most 250 <what> (...), got <count>" past kMaxReferenceFragments, else success.
Status check_reference_size(std::size_t count, const char* what);

/// The cgal-clip reference fracturer; it replays cut plans (CutPlanReplay) and cuts by given planes
/// (PlaneCutting).
class CgalClipFracturer final : public Fracturer, public PlaneCutting, public CutPlanReplay {
 public:
  [[nodiscard]] std::string_view name() const override { return "cgal-clip"; }
  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid,
                                                       const FractureParams& params) const override;
  /// The exact reference: the others are replayed with it.
  [[nodiscard]] bool exact_reference() const override { return true; }
  /// This fracturer: it replays cut plans.
  [[nodiscard]] const CutPlanReplay* cut_plan_replay() const override { return this; }
  /// This fracturer: it cuts by given planes.
  [[nodiscard]] const PlaneCutting* plane_cutting() const override { return this; }
  /// Replays `plan` exactly: fracture() for a recursive schedule, fracture_by_planes() for planes,
  /// fracture_by_cells() for cells.
  [[nodiscard]] Result<std::vector<Fragment>> replay(const Mesh& solid, const CutPlan& plan) const override;
  /// fracture_by_planes(solid, planes).
  [[nodiscard]] Result<std::vector<Fragment>> cut_by_planes(const Mesh& solid,
                                                            std::span<const Plane> planes) const override;
  /// Cuts `solid` by each plane in turn, as PlaneSliceFracturer::fracture_by_planes.
  [[nodiscard]] Result<std::vector<Fragment>> fracture_by_planes(const Mesh& solid,
                                                                 std::span<const Plane> planes) const;
  /// For each cell in order, the connected parts of (solid ∩ cell), ordered by order_parts
  /// (recursive_slicing.h), appended; a cell that misses the solid gives nothing. Faces of the solid
  /// keep their tags, faces made by a cell's planes are tagged cut. The contract a cell fracturer
  /// follows so that its fragments match these one to one. Error for a non-finite plane or a zero
  /// normal, a bad or self-intersecting solid, or a step CGAL cannot complete.
  [[nodiscard]] Result<std::vector<Fragment>> fracture_by_cells(const Mesh& solid,
                                                                std::span<const ConvexCell> cells) const;
};

/// Registers "cgal-clip" (no settings).
void register_cgal_clip(FracturerRegistry& registry);

}  // namespace shatter
