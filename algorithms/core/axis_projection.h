#pragma once
/// The axis-aligned projection of a plane's points to 2D in which the plane's normal points towards
/// the viewer: drop the normal's largest coordinate and order the other two so that a polygon
/// counter-clockwise about the normal stays counter-clockwise in 2D. Exact (no arithmetic), so exact
/// 2D predicates on the projected points decide 3D orientations in the plane. Used to triangulate caps,
/// and by the self-intersection check and its height-field stars.

#include "algorithms/core/mesh.h"

#include <cmath>
#include <utility>

namespace shatter {

/// The coordinate axis of `normal`'s largest magnitude (the first of equal ones).
inline int dominant_axis(const Vec3& normal) {
  int k = 0;
  if (std::abs(normal.y()) > std::abs(normal[k])) k = 1;
  if (std::abs(normal.z()) > std::abs(normal[k])) k = 2;
  return k;
}

/// `p` projected along coordinate `axis`, the other two in cyclic order (y z, z x or x y): the
/// orientation of projected points is the sign of component `axis` of their 3D normal.
inline Vec2 drop_axis(const Vec3& p, int axis) { return {p[(axis + 1) % 3], p[(axis + 2) % 3]}; }

/// Projection along the dominant axis of a plane normal.
struct AxisProjection {
  int u = 0;  ///< coordinate that becomes x
  int v = 1;  ///< coordinate that becomes y
  explicit AxisProjection(const Vec3& normal) {
    const int k = dominant_axis(normal);
    u = (k + 1) % 3;
    v = (k + 2) % 3;
    if (normal[k] < 0) std::swap(u, v);
  }
  /// `p` projected.
  [[nodiscard]] Vec2 operator()(const Vec3& p) const { return {p[u], p[v]}; }
};

}  // namespace shatter
