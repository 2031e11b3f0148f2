#pragma once
/// The repair's fallback: a new surface wrapped around the old one (CGAL's 3D alpha wrapping).
///
/// Design note: when CGAL's exact steps leave no valid solid (autorefinement fails or rounding makes
/// an intersection again, a border that triangulate_hole cannot close, shells that bound no volume),
/// the repair wraps the surface: alpha_wrap_3 returns a closed 2-manifold without self-intersections
/// that contains the input, at distance `offset` outside it, and does not enter cavities or notches
/// narrower than `alpha`. Both are fractions of the bounding box diagonal (docs/repair.md). Every face
/// of a wrap is new (FaceTag::repair): none is a piece of the input.

#include "algorithms/repair/repair_surface.h"

namespace shatter::repair {

/// Replaces `surface` by its alpha wrap (all faces origin -1); `alpha` and `offset` are fractions of
/// the surface's bounding box diagonal. False when the wrap is empty.
bool wrap_surface(SurfaceMesh& surface, double alpha, double offset);

}  // namespace shatter::repair
