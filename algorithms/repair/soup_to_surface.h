#pragma once
/// Step 1 of the repair: a triangle soup cleaned, oriented and made into a halfedge surface.

#include "algorithms/core/mesh.h"
#include "algorithms/repair/repair_surface.h"

namespace shatter::repair {

/// The surface made from a soup and what cleaning it removed.
struct SoupSurface {
  SurfaceMesh surface;      ///< oriented per connected part (orient_polygon_soup), origins set
  int vertices_merged = 0;  ///< input vertices welded into another at the same position
  int faces_removed = 0;    ///< input triangles dropped: repeated corners, duplicates of another
};

/// Runs CGAL's merge_duplicate_points_in_polygon_soup and repair_polygon_soup (welds equal positions,
/// drops triangles with repeated corners and duplicate triangles of either orientation),
/// orient_polygon_soup (reverses triangles to orient each part; a vertex or edge where parts cannot
/// agree is split) and polygon_soup_to_polygon_mesh. Each face's origin is the input triangle with
/// the same corner positions (the first one when duplicates were merged).
SoupSurface soup_to_surface(const Mesh& soup);

}  // namespace shatter::repair
