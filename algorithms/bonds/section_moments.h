#pragma once
/// Area moments of plane regions made of convex polygons, and the convex clipping that builds them.
///
/// Design note: a bond's contact region is the union of the overlaps of two fragments' opposite cut
/// triangles. Those overlaps do not intersect each other (each fragment's faces tile its boundary), so
/// the region's moments are plain sums of per-polygon moments. Moments are accumulated about a local
/// origin near the region (the caller's choice) and shifted to the centroid only at the end, which keeps
/// the parallel-axis subtraction free of cancellation for regions far from the world origin.

#include "algorithms/core/mesh.h"

#include <vector>

namespace shatter {

/// Sutherland-Hodgman clipping of `subject` (any simple polygon) by the convex, counter-clockwise
/// polygon `clip`; 2D points in m. Returns the (possibly empty) intersection polygon, counter-clockwise.
std::vector<Vec2> clip_convex(const std::vector<Vec2>& subject, const std::vector<Vec2>& clip);

/// Zeroth, first and second area moments of a plane region, accumulated polygon by polygon.
struct AreaMoments {
  double area = 0.0;      ///< m^2
  double first_x = 0.0;   ///< integral of x dA, m^3
  double first_y = 0.0;   ///< integral of y dA, m^3
  double second_xx = 0.0; ///< integral of x^2 dA, m^4
  double second_yy = 0.0; ///< integral of y^2 dA, m^4
  double second_xy = 0.0; ///< integral of x y dA, m^4

  /// Adds a simple counter-clockwise polygon (a clockwise one subtracts).
  void add_polygon(const std::vector<Vec2>& polygon);
};

/// Second moments of a plane region about its centroid, in principal axes.
struct PrincipalSection {
  Vec2 centroid = Vec2::Zero();   ///< m, in the accumulation frame
  Vec2 axis_1 = Vec2::UnitX();    ///< unit principal direction 1
  Vec2 axis_2 = Vec2::UnitY();    ///< unit principal direction 2 (axis_1 rotated +90 degrees)
  double moment_1 = 0.0;          ///< I_1 = integral of (distance from axis_1)^2 dA, m^4 (largest)
  double moment_2 = 0.0;          ///< I_2 = integral of (distance from axis_2)^2 dA, m^4
};

/// Centroid and principal second moments of `m` (requires m.area > 0).
PrincipalSection principal_section(const AreaMoments& m);

}  // namespace shatter
