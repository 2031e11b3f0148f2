#pragma once
/// Step 2 of the repair: borders that coincide stitched together, degenerate faces removed.

#include "algorithms/repair/repair_surface.h"

namespace shatter::repair {

/// Runs CGAL's stitch_borders (border edges with the same end positions become one edge),
/// merge_duplicated_vertices_in_boundary_cycles (a border cycle passing twice through one position is
/// pinched there) and remove_degenerate_faces (zero-area faces collapsed or flipped away). Returns the
/// number of faces removed.
int stitch_surface(SurfaceMesh& surface);

}  // namespace shatter::repair
