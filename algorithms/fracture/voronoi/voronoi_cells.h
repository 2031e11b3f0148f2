#pragma once
/// The Voronoi diagram of the sites restricted to a box, as approximate convex cells: which bisector
/// planes to try for each cell, in which order, and how far each cell reaches.
///
/// Design note: the cells are computed in plain double (the box clipped by the bisector planes,
/// cell_polytope.h), so they are only used for decisions that stay valid under a margin: the bounding
/// box of a cell, inflated by `margin`, certainly holds the exact cell, and the polytope's faces say
/// which bisector bounds which face. The exact side tests on the mesh are done on the bisector planes
/// themselves (bisector_plane), never on these polygons.

#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/fracture/voronoi/cell_polytope.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// The bisector plane between sites i and j (m): its negative side is the half-space closer to
/// sites[i]. The plane of (j, i) is the same point with the opposite normal, so the two cells that
/// share it get exactly complementary side tests.
Plane bisector_plane(std::span<const Vec3> sites, int i, int j);

/// One site's cell: the other sites by increasing distance, and the cell's bounding box.
struct VoronoiCell {
  /// Other site indices, nearest first (ties by index), up to the farthest whose bisector can bound
  /// the cell inside the box: every face of the cell lies on the bisector of one of them.
  std::vector<std::int32_t> neighbours;
  Aabb bounds;                           ///< box of the cell clipped to the input box, inflated, m
  /// The cell clipped to the input box, face labels indexing `neighbours` (not ok when a corner fell
  /// exactly on a plane: then `bounds` is the whole box).
  CellPolytope polytope;
};

/// Cells of `sites` (#S distinct finite points, m) clipped to `box` (m), each box and reach inflated
/// by `margin` (m). The neighbours come from a uniform grid over the sites: time about linear in #S for
/// sites spread through the box (each cell reads the buckets within twice its reach), O(#S^2 log #S) at
/// worst; the result is the same as with a full sort of the other sites.
std::vector<VoronoiCell> voronoi_cells(std::span<const Vec3> sites, const Aabb& box, double margin);

}  // namespace shatter
