#pragma once
/// A solid from any triangle soup: what a user's mesh file needs before a fracturer can take it.
///
/// Design note: artists export open meshes, shells of mixed orientation, self-intersecting parts and
/// duplicated seam vertices; every fracturer needs a closed, consistently oriented solid without
/// self-intersections (validate_solid, the one acceptance rule). The repair runs CGAL's Polygon Mesh
/// Processing steps in a fixed order and reports each (docs/repair.md); it is offline work (loading,
/// never timed as a fracture). The caller runs it on meshes the acceptance rule refuses; a valid solid
/// passes through with its triangles unchanged (vertices renumbered), Hausdorff distance 0.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/repair/hausdorff_distance.h"

#include <string>

namespace shatter {

/// What repair_solid changed. Counts are of the input's elements unless said otherwise.
struct RepairReport {
  bool repaired = false;              ///< anything below is non-zero: the solid differs from the input
  int vertices_merged = 0;            ///< vertices welded into another with the same position
  int faces_removed = 0;              ///< degenerate or duplicate faces dropped (soup cleaning, stitching)
  int faces_reoriented = 0;           ///< faces reversed to orient their shell consistently
  int holes_filled = 0;               ///< border cycles closed by new faces (tagged FaceTag::repair)
  double hole_area = 0.0;             ///< area of those new faces, m^2
  int self_intersections = 0;         ///< intersecting face pairs (CGAL's count) of the closed surface, 0 when the project's test finds none
  std::string self_intersection_fix;  ///< "" (none needed), "autorefine", or "alpha-wrap" (the one fallback, whatever failed)
  int sheets_removed = 0;             ///< open parts that enclose no volume, dropped beside a solid
  int shells = 0;                     ///< closed shells of the result
  int cavities = 0;                   ///< of those, inward-facing shells inside another (cavities)
  double time_ms = 0.0;               ///< wall time of the repair, ms (offline: never in a fracture's time)
  double hausdorff_distance = 0.0;    ///< approximate symmetric Hausdorff distance input <-> result, m
};

/// The repaired solid and what was done to it.
struct RepairedSolid {
  Mesh mesh;            ///< closed, outward, no self-intersection; input faces tagged as given, new faces FaceTag::repair
  RepairReport report;  ///< what changed
};

/// Settings of repair_solid; every length is relative to the input, so none has a unit.
struct RepairOptions {
  /// An open part is a solid with holes when (volume its filling encloses) / (filling area)^(3/2),
  /// its depth / width, is at least this; else an open sheet, dropped (docs/repair.md "Holes or sheets").
  double min_depth_ratio = 0.05;
  /// Fill holes with CGAL's triangulate_refine_and_fair_hole instead of triangulate_hole (a smooth
  /// patch instead of the flat minimal one; off: docs/repair.md "Repair steps" has the figures).
  bool refine_and_fair_holes = false;
  /// The fallback wrap: alpha (no ball of this radius passes through it), fraction of the bbox diagonal.
  double wrap_alpha = 1.0 / 50.0;
  /// The fallback wrap: its distance outside the input, fraction of the bbox diagonal.
  double wrap_offset = 1.0 / 600.0;
  /// Sampling of the Hausdorff distance.
  repair::HausdorffSampling hausdorff;
};

/// Repairs `soup` into a solid (see the design note) or says why none exists, in one line that starts
/// with `what` (for example "bunny.off: an open sheet encloses no volume"). The input's tags are kept on
/// the faces that survive; faces the repair adds are tagged FaceTag::repair.
Result<RepairedSolid> repair_solid(const Mesh& soup, const std::string& what, const RepairOptions& options = {});

}  // namespace shatter
