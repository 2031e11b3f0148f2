#pragma once
/// Runtime fracture of a fractured structure: only the fragments an impact reaches are fractured; the
/// rest are neither copied nor validated again (a scene only pays for what the hit changes).

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <span>
#include <vector>

namespace shatter {

/// The fragments one impact fractured and what they became.
struct LocalFracture {
  std::vector<int> hit;                       ///< indices into the input fragments, ascending
  std::vector<std::vector<Fragment>> pieces;  ///< per hit fragment, the fragments it broke into
};

/// Which fragments `impact` reaches: those whose surface comes within `impact.radius` of the impact
/// point or that contain it. With radius 0, the one fragment that contains the point, else the
/// nearest one. Bounding boxes are tested first, so far fragments cost one box test each.
std::vector<int> fragments_near_impact(std::span<const Fragment> fragments, const Impact& impact);

/// Fractures each fragment `impact` reaches with `fracturer` (`params.fragments` pieces each, the
/// impact passed on) and returns only those. The others stay where they are, untouched.
Result<LocalFracture> fracture_near_impact(const Fracturer& fracturer, std::span<const Fragment> fragments,
                                           const Impact& impact, const FractureParams& params);

}  // namespace shatter
