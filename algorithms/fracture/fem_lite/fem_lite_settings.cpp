#include "algorithms/fracture/fem_lite/fem_lite_settings.h"

#include "algorithms/core/material.h"

#include <cmath>
#include <string>

namespace shatter {

Status check_fem_lite_settings(const FemLiteSettings& settings) {
  if (settings.resolution < 2 || settings.resolution > kFemLiteMaxResolution)
    return Error{"fem-lite: resolution must be in [2, " + std::to_string(kFemLiteMaxResolution) + "], got " +
                 std::to_string(settings.resolution)};
  if (settings.max_cells < 0 || settings.max_cells > kFemLiteMaxCells)
    return Error{"fem-lite: max_cells must be in [0, " + std::to_string(kFemLiteMaxCells) + "], got " +
                 std::to_string(settings.max_cells)};
  if (Status s = check_material(settings.material); !s) return Error{"fem-lite: " + s.error().message};
  if (!settings.gravity.allFinite()) return Error{"fem-lite: gravity must be finite"};
  for (std::size_t i = 0; i < settings.supports.size(); ++i) {
    const Aabb& box = settings.supports[i];
    if (!box.min.allFinite() || !box.max.allFinite() || (box.min.array() > box.max.array()).any())
      return Error{"fem-lite: supports[" + std::to_string(i) + "] must be a finite box with min <= max"};
  }
  if (!(std::isfinite(settings.contact_time) && settings.contact_time > 0.0))
    return Error{"fem-lite: contact_time must be a finite number of seconds > 0, got " +
                 std::to_string(settings.contact_time)};
  if (!(std::isfinite(settings.crack_spacing) && settings.crack_spacing >= 0.0))
    return Error{"fem-lite: crack_spacing must be finite and >= 0, got " + std::to_string(settings.crack_spacing)};
  if (!(settings.min_piece_share >= 0.0 && settings.min_piece_share < 1.0))
    return Error{"fem-lite: min_piece_share must be in [0, 1), got " + std::to_string(settings.min_piece_share)};
  return {};
}

}  // namespace shatter
