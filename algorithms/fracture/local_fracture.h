#pragma once
/// Runtime fracture of a fractured structure: only the fragments an impact reaches are fractured; the
/// rest are neither copied nor validated again (a scene only pays for what the hit changes).

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <cstdint>
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

/// How fragments_near_impact searches.
struct NearImpactOptions {
  /// When not empty (one entry per fragment), only fragments whose entry is non-zero can be hit.
  std::span<const std::uint8_t> eligible;
  /// Reject fragments by bounding box before measuring their surface. Off, every eligible fragment's
  /// surface is measured: the same answer (a box is never farther than the surface it holds), at
  /// full cost; the frame pipeline's no-skip mode uses that to prove the cull result-neutral.
  bool cull_by_box = true;
};

/// fragments_near_impact over the eligible fragments only, with the cull chosen by `options`.
std::vector<int> fragments_near_impact(std::span<const Fragment> fragments, const Impact& impact,
                                       const NearImpactOptions& options);

/// Fractures each fragment `impact` reaches with `fracturer` (`params.fragments` pieces each, the
/// impact passed on) and returns only those. The others stay where they are, untouched.
Result<LocalFracture> fracture_near_impact(const Fracturer& fracturer, std::span<const Fragment> fragments,
                                           const Impact& impact, const FractureParams& params);

}  // namespace shatter
