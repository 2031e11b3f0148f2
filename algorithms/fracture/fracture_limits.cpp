#include "algorithms/fracture/fracture_limits.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/representable_range.h"
#include "algorithms/core/solid_check.h"

#include <cmath>
#include <string>

namespace shatter {

Status check_fracture_solid(const Mesh& solid, std::string_view algorithm, SelfIntersectionVerdicts* verdicts,
                            AttributeValues values) {
  if (Status s = check_attributes(solid, std::string(algorithm), values); !s) return s;
  return check_solid(solid, algorithm, verdicts);
}

Status check_fracture_request(const FractureParams& params, std::string_view algorithm, int max_fragments) {
  if (params.fragments < 1 || params.fragments > max_fragments)
    return Error{std::string(algorithm) + ": fragments must be between 1 and " + std::to_string(max_fragments) +
                 ", got " + std::to_string(params.fragments)};
  if (params.impact) {
    const Impact& i = *params.impact;
    if (!within_coordinate_range(i.point) || !i.direction.allFinite() || !std::isfinite(i.impulse) ||
        !(i.radius >= 0.0 && i.radius <= kMaxCoordinate))
      return Error{std::string(algorithm) + ": the impact needs a point within +-1e9 m, a finite direction and "
                   "impulse and a radius in [0, 1e9] m"};
  }
  return {};
}

Status check_fracture_params(const Mesh& solid, const FractureParams& params, std::string_view algorithm,
                             int max_fragments) {
  if (Status s = check_fracture_request(params, algorithm, max_fragments); !s) return s;
  return check_fracture_solid(solid, algorithm, params.verdicts);
}

Status check_planes(std::span<const Plane> planes) {
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Plane& p = planes[i];
    if (!within_coordinate_range(p.point) || !within_coordinate_range(p.normal) || p.normal.squaredNorm() == 0.0)
      return Error{"plane " + std::to_string(i) +
                   " needs a point within +-1e9 m and a non-zero normal with components within +-1e9"};
  }
  return {};
}

}  // namespace shatter
