#pragma once
/// Fan triangulation of a cap whose outline is one strictly convex counter-clockwise loop.
///
/// Design note: a Voronoi cell is convex, so every face of it that lies inside the solid gives a cap
/// that is the face's convex polygon, and a face crossing a locally convex part of the surface often
/// does too. Such a cap needs no Delaunay triangulation: a fan from one corner covers it. The test is
/// exact (orient2d and coordinate comparisons on the points as given) and takes O(n): the edges form
/// one loop, every corner turns strictly left, and the loop turns around once, which holds when the
/// lexicographically smallest corner is the only local minimum of the cycle in that order (a loop with
/// only left turns that winds k times has k such minima). Anything else (reflex, collinear or nearly
/// straight corners, whose sine of turn is below 1e-9: points of one straight side rounded apart,
/// where a fan would make a sliver folded onto the surface's own triangles,
/// several loops, holes, clockwise loops, coordinates far outside 2^-400..2^400 where the predicates
/// lose exactness) is declined, and the caller triangulates the cap with triangulate_cap.

#include "algorithms/core/mesh.h"
#include "algorithms/core/cap_triangulator.h"

#include <span>
#include <vector>

namespace shatter {

/// When `edges` (over indices into `points`) form a single strictly convex counter-clockwise loop,
/// replaces `triangles` with its fan (#edges - 2 triangles over the input indices, counter-clockwise)
/// and returns true. Otherwise returns false and leaves `triangles` untouched.
bool fan_convex_cap(std::span<const Vec2> points, std::span<const CapEdge> edges, std::vector<Triangle>& triangles);

}  // namespace shatter
