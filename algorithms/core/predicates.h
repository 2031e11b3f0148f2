#pragma once
/// Exact geometric predicates on double inputs: a fast floating-point filter, and an exact
/// expansion-arithmetic fallback when the filter cannot decide. The sign returned is always the sign
/// of the exact real-number expression over the given doubles.

#include "algorithms/core/mesh.h"

namespace shatter {

/// Sign of dot(normal, p - origin): +1 on the positive side, -1 on the negative side, 0 exactly on.
int plane_side(const Vec3& p, const Vec3& origin, const Vec3& normal);

/// plane_side with a snap: 0 also when the computed dot(normal, p - origin) is within `snap_dot` of
/// zero, and then `snapped` is set when the exact side is not 0. One rounded dot product for the
/// vertices clear of the snap band, as plane_side's filter.
int plane_side_snapped(const Vec3& p, const Vec3& origin, const Vec3& normal, double snap_dot, bool& snapped);

/// Sign of the signed area of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// +1 when d lies strictly inside the circle through a, b, c (a, b, c counter-clockwise),
/// -1 strictly outside, 0 on it.
int incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Sign of the volume of the tetrahedron (a, b, c, d): +1 when d lies below the plane of a, b, c
/// (a, b, c counter-clockwise seen from above), -1 above, 0 coplanar.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace shatter
