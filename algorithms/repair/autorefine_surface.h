#pragma once
/// Step 4 of the repair: self-intersections resolved by CGAL's autorefinement in exact arithmetic.
///
/// Design note: autorefine_and_remove_self_intersections splits the triangles along every
/// intersection and removes the patches that lie inside the solid (so two overlapping boxes become
/// their union). It needs exact constructions (the intersection points), so the surface is copied to
/// an Exact_predicates_exact_constructions_kernel mesh and rounded back to doubles afterwards.
/// Rounding moves points by half an ulp, which can make a new intersection or a zero-area triangle;
/// the rounded surface is therefore tested again with the project's exact test
/// (find_self_intersection), and the caller falls back to a wrap when it fails. The autorefinement
/// also fails silently where the surface around an intersection is folded or was open (it keeps the
/// wrong patches: a dragon of CGAL's data set came out as 18 triangles); a result with less than
/// half the volume of the largest connected part it started from counts as failed too.

#include "algorithms/repair/repair_surface.h"

#include <string>

namespace shatter::repair {

/// What autorefine_surface did.
struct Autorefinement {
  int pairs = 0;        ///< intersecting face pairs found before (CGAL's self_intersections), 0 when none
  bool resolved = true; ///< the surface, rounded to doubles, no longer intersects itself
  std::string failure;  ///< why not, when !resolved
};

/// Counts the self-intersecting face pairs of `surface`; when there are any, autorefines it and
/// removes the inner patches (pieces of a face keep its origin), rounds to doubles and checks the
/// result. On failure `surface` is left as it was.
Autorefinement autorefine_surface(SurfaceMesh& surface);

}  // namespace shatter::repair
