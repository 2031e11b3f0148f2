#pragma once
/// Where the Voronoi sites of a fracture go: uniformly inside the solid, or clustered around an impact.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/voronoi/point_in_mesh.h"

#include <cstdint>
#include <vector>

namespace shatter {

/// How sites are placed around an impact (ignored without an impact or with radius 0).
struct SiteSettings {
  /// Share of the sites drawn uniformly in the ball of the impact radius, in [0, 1]; default 0.5.
  double impact_share = 0.5;
  /// Draws allowed per site before giving up (a thin solid fills little of its box); default 2000.
  int max_draws_per_site = 2000;
};

/// `params.fragments` distinct sites (m) strictly inside the closed outward `solid`, deterministic in
/// `params.seed` (SplitMix64).
///
/// Without an impact (or with radius 0) the sites are uniform in the solid (rejection sampling in its
/// bounding box). With an impact of radius r > 0 at point c, a share `impact_share` of them is uniform
/// in the part of the ball B(c, r) inside the solid, and the rest at distance d from c uniform in
/// [r, D] (D: farthest corner of the bounding box) in a uniform direction, which is a density falling
/// as 1 / d^2: fragments are small near the impact and grow with the distance from it. Sites the ball
/// cannot hold (it barely meets the solid) fall back to the outer distribution. Each distribution is
/// drawn only where it can reach the solid's bounding box (the same law restricted to a region that
/// holds the solid), so a small solid far from the impact, a runtime piece, wastes few draws.
/// A solid so thin that the draws run out (a sliver fragment fractured again at runtime) gets the sites
/// found so far: fewer fragments than requested, which the fragment count of the metrics shows, rather
/// than a failed frame. With none found, one site at the box centre: one cell, the whole solid.
Result<std::vector<Vec3>> sample_sites(const Mesh& solid, const FractureParams& params,
                                       const SiteSettings& settings = {});

/// The same with the solid's inside test already built (it is shared with the cell clipper).
Result<std::vector<Vec3>> sample_sites(const PointInMesh& inside, const FractureParams& params,
                                       const SiteSettings& settings = {});

}  // namespace shatter
