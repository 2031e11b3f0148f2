#pragma once
/// The volume enclosed by the convex hull of a point set, for the colliders' error figures.

#include "algorithms/core/mesh.h"

#include <span>

namespace shatter {

/// Volume of the convex hull of `points`, m^3 (0 when they span no volume). The hull is CGAL's
/// convex_hull_3 on exact predicates, so its faces are triangles of the input points themselves and the
/// hull of a subset never comes out larger; the volume is summed in double relative to one point.
[[nodiscard]] double convex_hull_volume(std::span<const Vec3> points);

}  // namespace shatter
