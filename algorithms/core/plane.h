#pragma once
/// An oriented plane given by a point on it and a normal (not necessarily unit length).
///
/// Design note: the plane is kept as point + normal, exactly as the user or the random generator gave
/// it, never as (n, d): d = -n.p is not representable in double, and the exact side test
/// `sign(n . (x - p))` (predicates.h) is only exact on the original numbers.

#include "algorithms/core/mesh.h"

namespace shatter {

/// An oriented plane; the positive side is where `normal` points.
struct Plane {
  Vec3 point = Vec3::Zero();       ///< a point on the plane, m
  Vec3 normal = Vec3::UnitZ();     ///< direction of the positive side (any non-zero length)
};

}  // namespace shatter
