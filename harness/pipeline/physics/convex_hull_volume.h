#pragma once
/// The volume enclosed by the convex hull of a point set, for the colliders' error figure.

#include "algorithms/core/mesh.h"

#include <span>

namespace shatter {

/// Volume of the convex hull of `points`, m^3 (0 when they span no volume). The hull's faces come
/// from Bullet's btConvexHullComputer (exact integer arithmetic on the points scaled to a fixed grid);
/// the volume is summed in double from the input points themselves, each face fanned from its first
/// corner.
[[nodiscard]] double convex_hull_volume(std::span<const Vec3> points);

}  // namespace shatter
