#pragma once
/// Step 6 of the repair: how far the repaired surface lies from the input surface.
///
/// Design note: the input may be non-manifold, open or self-intersecting, so it is sampled and
/// searched as a triangle soup (area-weighted sampling of its own, CGAL's AABB tree of its triangles,
/// queried without the search hint, which changed results between processes), never as a halfedge
/// mesh. Each surface is sampled at its vertices plus `points_per_face * #F` points (at least
/// `min_points`) uniformly at random over its area with a fixed seed (SplitMix64), so the figure is
/// the same in every run; each sample's distance to the other surface is exact. The result is the larger of
/// the two one-sided maxima: a lower bound of the true Hausdorff distance that misses it by at most
/// about the gap between samples (docs/repair.md, "Hausdorff distance").

#include "algorithms/core/mesh.h"

namespace shatter::repair {

/// Sampling of hausdorff_distance.
struct HausdorffSampling {
  int min_points = 20000;      ///< random points on a surface's faces, at least
  double points_per_face = 2;  ///< random points per triangle, when that gives more
};

/// Approximate symmetric Hausdorff distance between the surfaces of two triangle soups, m (0 when
/// either has no triangle with area).
double hausdorff_distance(const Mesh& a, const Mesh& b, const HausdorffSampling& sampling = {});

}  // namespace shatter::repair
