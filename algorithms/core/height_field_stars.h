#pragma once
/// Vertices whose star (the triangles that use the vertex) is a height field: the graph of a function
/// over one coordinate plane. Two triangles of such a star have no point in common other than the
/// vertex and the edge they share, so a self-intersection test needs no test for a pair of triangles
/// that share such a vertex, which on a surface mesh is nearly every pair whose boxes overlap.
///
/// Exact test (orient2d and coordinate comparisons on the stored doubles) of vertex v, projected along
/// the largest component of the star's summed normal:
/// - every triangle (v, a, b) of the star projects to a triangle of one strict orientation, so its
///   link edge a -> b turns the direction from v by an angle strictly between 0 and pi;
/// - the link edges form a permutation of the link's vertices (each leaves one once and enters one
///   once), so they close into cycles, and each cycle winds around v at least once;
/// - the projected link winds around v exactly once, counted as its crossings of the ray from v along
///   +x (a turn of less than pi crosses it exactly when it goes from the lower half-plane to the upper).
/// So the link is one cycle whose wedges cover the plane around v once: the projection is one to one
/// on the star.

#include "algorithms/core/mesh.h"

#include <cstdint>
#include <vector>

namespace shatter {

/// Per vertex of `mesh`: 1 when its star passes the test above, else 0 (also for a vertex no triangle
/// uses). O(#F + #V).
std::vector<std::uint8_t> height_field_stars(const Mesh& mesh);

}  // namespace shatter
