#pragma once
/// A bounded convex polyhedron with exact vertices, built by clipping a box with half-spaces: the mesh
/// of one cell for cgal-clip's cell fracture. Includes CGAL: only for files of this folder.
///
/// Design note: each vertex is made as the intersection of three of the given planes, never from an
/// earlier constructed vertex, so the exact numbers stay as small as the input allows however many
/// planes cut the cell (chaining edge-plane intersections makes every clip multiply their size). The
/// side of every vertex is an exact predicate, so a plane through a vertex, an edge or a face is
/// decided exactly and every vertex is a true corner: faces are strictly convex polygons and a fan
/// triangulates them without flat triangles.

#include "algorithms/fracture/cgal_clip/cgal_exact_mesh.h"

#include <array>
#include <vector>

namespace shatter::cgal_exact {

/// A convex polyhedron with non-empty interior, or empty.
class ExactConvexPolytope {
 public:
  /// The axis-aligned box [lower, upper] (lower < upper in every coordinate).
  ExactConvexPolytope(const Vec3& lower, const Vec3& upper);

  /// Keeps the part on the negative side of `plane` (closed); `source` identifies the plane for
  /// face_sources(). Becomes empty when that part has no interior. Throws ClipFailure on a broken
  /// invariant.
  void clip(const ExactPlane& plane, int source);

  /// True when no interior is left.
  [[nodiscard]] bool empty() const { return faces_.empty(); }

  /// Lower and upper corners of a box containing every vertex (from interval approximations: never
  /// smaller than the exact bounding box), m.
  [[nodiscard]] std::array<Vec3, 2> bounds() const;

  /// The `source` of the plane of every face, one per face in face order (-1 for the box's faces).
  [[nodiscard]] std::vector<int> face_sources() const;

  /// The boundary as a closed, outward triangle mesh (fan per face).
  [[nodiscard]] SurfaceMesh triangle_mesh() const;

 private:
  /// A face: its plane (index into planes_) and corners counter-clockwise seen from outside.
  struct Face {
    int plane = 0;
    std::vector<int> corners;
  };

  std::vector<ExactPlane> planes_;  ///< every plane that made a face, box first
  std::vector<int> sources_;        ///< source of each plane in planes_
  std::vector<ExactPoint> points_;  ///< vertices, each the intersection of three planes
  std::vector<Face> faces_;         ///< boundary faces
};

}  // namespace shatter::cgal_exact
