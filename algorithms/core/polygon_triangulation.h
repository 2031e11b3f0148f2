#pragma once
/// Triangulation of one polygon face of a mesh file, in O(n log n) for n corners: a convex quad is
/// split along a diagonal; any other polygon is projected on the plane of its two largest normal
/// components and triangulated by the constrained Delaunay triangulation of cap_triangulator.h (exact
/// predicates, so the result does not depend on rounding). The triangles keep the polygon's winding.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// Appends the triangles of polygon `poly` (indices into `vertices`, at least 3) to `out`. A simple
/// polygon of n corners gives n - 2 triangles covering its area; corners on a straight line are
/// kept as triangle corners. A polygon whose projection crosses itself is an error (the message says
/// so, the caller names the face); a polygon with no area in any projection is fanned from its first
/// corner (solid validation then refuses its zero-area triangles).
Status triangulate_polygon(const std::vector<Vec3>& vertices, std::span<const std::int32_t> poly,
                           std::vector<Triangle>& out);

}  // namespace shatter
