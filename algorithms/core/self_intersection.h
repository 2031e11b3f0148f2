#pragma once
/// Exact self-intersection test of a triangle mesh: do two of its triangles meet anywhere other than
/// at the corners and the edge they share?
///
/// Design note: fracturers whose caps are bounded by the cut outline (voronoi, fem-lite) cannot give
/// a partition of a solid whose surface crosses itself (the outline then crosses itself), so they
/// refuse such input up front, as the exact reference does (CGAL's does_self_intersect). The test
/// has to cost little next to a fracture: triangles are binned in a uniform grid whose cell is about
/// the mean triangle's extent, each pair of triangles sharing a cell with overlapping boxes is tested
/// once (in the cell of the lower corner of the boxes' overlap). A pair that shares a vertex whose
/// star is a height field (height_field_stars.h, on smooth meshes nearly every vertex and 97 % of the
/// pairs) needs no test; most other pairs are settled by three plane-side tests. Every decision is an exact predicate (orient3d, orient2d) on the stored doubles.
/// Corners count as shared when their positions are equal (not only their indices), so sheets split
/// at a pinched vertex, which touch there, are not reported.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/core/self_intersection_verdicts.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace shatter {

/// True when the closed triangles t and u (corners, m) have a point in common other than their
/// common corners and the edge between two common corners. Two copies of one triangle intersect.
/// Zero-area triangles, which mesh validation refuses, are mostly reported as meeting nothing, and
/// for them the answer may depend on which one is t (find_self_intersection passes the lower index
/// as t, as testing every pair in order does).
bool triangles_intersect(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u);

/// The first pair of triangles of `mesh` (indices, smaller first, in the grid's order) that
/// intersect (triangles_intersect), or nothing. O(#F) on a surface-like mesh.
std::optional<std::array<std::int32_t, 2>> find_self_intersection(const Mesh& mesh);

/// The first pair of triangles of `mesh` from different parts (`part`: one label per triangle, for
/// example its shell) that intersect, or nothing. Pairs within one part are not tested; the cost is
/// that of find_self_intersection.
std::optional<std::array<std::int32_t, 2>> find_intersection_between_parts(const Mesh& mesh,
                                                                           std::span<const std::int32_t> part);

/// Error "<who>: the input mesh intersects itself (triangles i and j)" when find_self_intersection
/// finds a pair, else success. With `verdicts`, a clean verdict is remembered there by the mesh's
/// fingerprint (self_intersection_verdicts.h) and the same mesh is not tested again: the test costs
/// about 0.3 us per triangle, more than a 5-fragment Voronoi fracture, while games and the grid break
/// the same solid many times (every instance of an asset, every cell of a grid row). Without, every
/// call tests. A mesh that intersects itself is tested every time.
Status check_no_self_intersection(const Mesh& mesh, std::string_view who, SelfIntersectionVerdicts* verdicts);

}  // namespace shatter
