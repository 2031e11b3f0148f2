#pragma once
/// A collider's points under a vertex budget.
///
/// Design note: Bullet's convex hull shape finds a support point by scanning every point of the hull,
/// and a contact between two hulls costs tens of such scans a step, so a pile of fresh fragments
/// spends most of its physics step scanning points. A budget keeps the points that are extreme
/// along a fixed spread of directions: the 6 axis directions, the 8 cube diagonals, the 12 edge
/// directions, then points of a spherical Fibonacci set, in that order, so that every prefix is
/// spread over the sphere. The collider is the hull of a subset of the piece's own points: it lies
/// inside the piece's hull, never beyond it (pieces that start touching cannot start overlapping), and
/// the error is volume lost at the corners it cuts off (accuracy's collider figures).

#include "algorithms/core/mesh.h"
#include "harness/pipeline/physics/outer_points.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// Indices of at most `budget` (>= 4) of `points`: each the point farthest along one of the
/// directions above (the first such point on a tie), distinct, in the order their directions come.
/// Every index, in order, when there are `budget` points or fewer.
[[nodiscard]] std::vector<std::int32_t> collider_point_indices(std::span<const Vec3> points, int budget);

/// The vertices of `mesh` its collider is made of: those outer_point_indices keeps (every vertex when
/// `drop_inner_points` is false, or when it keeps fewer than 4), then at most `budget` of them by
/// collider_point_indices (0: all of them). `planes` is vertex_planes(mesh).
[[nodiscard]] std::vector<std::int32_t> collider_vertex_indices(const Mesh& mesh, const VertexPlanes& planes,
                                                                bool drop_inner_points, int budget);

}  // namespace shatter
