#pragma once
/// Step 3 of the repair: every border cycle filled, and open parts that enclose nothing dropped.
///
/// Design note (the sheet rule, docs/repair.md "Holes or sheets"): after filling, a connected part
/// that had borders encloses a volume V and its filling has area A. V / A is the mean depth of that
/// volume under its opening and sqrt(A) the opening's width; the part is a solid with holes when
/// depth / width = V / A^(3/2) is at least `min_depth_ratio` (a box missing a face: 1; a hemisphere
/// bowl: 0.38), and an open sheet otherwise (a flat quad: 0; a terrain patch a few percent). The rule
/// has no length unit, so it calls a part the same at every scale.

#include "algorithms/repair/repair_surface.h"

namespace shatter::repair {

/// What fill_holes did.
struct HoleFilling {
  int holes_filled = 0;     ///< border cycles closed by new faces (origin -1)
  double hole_area = 0.0;   ///< area of the new faces kept, m^2
  int holes_unfilled = 0;   ///< border cycles that triangulate_hole could not close (their parts are sheets)
  int sheets_removed = 0;   ///< parts with borders whose filling encloses too little (the sheet rule)
};

/// Fills every border cycle with CGAL's triangulate_hole (a minimum-weight triangulation of the
/// cycle, searched in its 3D Delaunay triangulation, or a 2D constrained Delaunay triangulation when
/// the cycle is flat; when that finds none, a search over all triangulations for cycles of up to
/// 300 edges), then removes each filled part whose depth / width ratio (see the design note)
/// is below `min_depth_ratio`, filling included, and each part with a border that no triangulation
/// closes (a flat sheet whose vertices all lie on its border: every triangulation repeats an edge). With `refine_and_fair`, each filling is instead
/// made by triangulate_refine_and_fair_hole (refined to the border's edge lengths, then faired to
/// continue the surrounding curvature; docs/repair.md measures both).
HoleFilling fill_holes(SurfaceMesh& surface, double min_depth_ratio, bool refine_and_fair = false);

}  // namespace shatter::repair
