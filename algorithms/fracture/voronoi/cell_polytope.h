#pragma once
/// One Voronoi cell as a convex polytope with its combinatorics: which plane bounds each face, which
/// face lies across each edge, and one shared position per corner.
///
/// Design note: the cell clipper (cell_clipper.h) builds each cap of a fragment from the solid's cut
/// outline inside one face plus the stretches of the face's edges that lie inside the solid, so it
/// needs, per face, its edges in order and the face across each of them. The polytope is computed in
/// double (the box clipped by the planes in order); a corner is made once, on the first face that
/// meets it, and shared by every face around it, so caps that meet at a corner meet exactly. A
/// polytope vertex exactly on a later plane would need a corner of four planes: the build then
/// reports failure and the caller takes the exact sequential path instead.

#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// A convex polytope bounded by labelled planes. Labels >= 0 index the caller's plane list; the six
/// box faces have labels -1 .. -6.
struct CellPolytope {
  /// One face, counter-clockwise seen from outside.
  struct Face {
    int label = 0;                      ///< the plane the face lies on
    std::vector<std::int32_t> corners;  ///< corner indices, in order
    std::vector<int> across;            ///< label of the face across the edge corners[k] -> corners[k+1]
  };
  std::vector<Vec3> corners;            ///< #C corner positions, m
  std::vector<Face> faces;              ///< faces that survived every plane
  bool ok = false;                      ///< false when a corner fell exactly on a later plane
};

/// The box `box` (m) as a polytope (ok).
CellPolytope box_polytope(const Aabb& box);

/// Clips `polytope` to the negative side of `plane`, whose face gets `label` (>= 0); a plane that
/// misses the polytope leaves no face. Sets `ok` to false when a corner lies exactly on the plane.
void clip_polytope(CellPolytope& polytope, const Plane& plane, int label);

/// Largest squared distance from `from` to a corner of the polytope's faces, m^2.
double max_corner_distance_squared(const CellPolytope& polytope, const Vec3& from);

/// The box `box` (m) clipped to the negative sides of `planes`, in order (labels: their indices).
CellPolytope cell_polytope(const Aabb& box, std::span<const Plane> planes);

}  // namespace shatter
