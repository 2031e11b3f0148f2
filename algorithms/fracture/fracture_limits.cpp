#include "algorithms/fracture/fracture_limits.h"

#include <cmath>
#include <string>

namespace shatter {

Status check_fracture_params(const FractureParams& params) {
  if (params.fragments < 1 || params.fragments > kMaxFragments)
    return Error{"fragments must be between 1 and " + std::to_string(kMaxFragments) + ", got " +
                 std::to_string(params.fragments)};
  if (params.impact) {
    const Impact& i = *params.impact;
    if (!i.point.allFinite() || !i.direction.allFinite() || !std::isfinite(i.impulse) ||
        !std::isfinite(i.radius) || i.radius < 0)
      return Error{"impact must have a finite point, direction and impulse and a radius >= 0"};
  }
  return {};
}

Status check_planes(std::span<const Plane> planes) {
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Plane& p = planes[i];
    if (!p.point.allFinite() || !p.normal.allFinite() || p.normal.squaredNorm() == 0.0)
      return Error{"plane " + std::to_string(i) + " needs a finite point and a finite non-zero normal"};
  }
  return {};
}

}  // namespace shatter
