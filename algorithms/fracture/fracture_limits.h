#pragma once
/// Checks of fracture parameters shared by every fracturer, with the documented limits.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/fracturer.h"

#include <span>

namespace shatter {

/// The largest fragment count a fracturer accepts (memory grows linearly with it).
inline constexpr int kMaxFragments = 100000;

/// Error unless 1 <= fragments <= kMaxFragments and the impact (if any) is finite.
Status check_fracture_params(const FractureParams& params);

/// Error unless every plane is finite with a non-zero normal.
Status check_planes(std::span<const Plane> planes);

}  // namespace shatter
