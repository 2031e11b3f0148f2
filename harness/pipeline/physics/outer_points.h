#pragma once
/// A piece's points that can be corners of its convex hull.
///
/// Design note: a plane-sliced piece carries every point where a cut crossed one of its edges, so a
/// slab-like piece of 9 corners often has 50 more points on the straight runs of its edges (and a
/// repaired or Voronoi piece may have points inside flat faces). None of them can be a corner of the
/// hull, yet Bullet scans every point of a hull for each support query, and computing the hull to drop
/// them costs more than the rest of the collider. A point is dropped here when its own faces prove it
/// inside the hull of its neighbours: it lies on the segment between two of them (an edge's straight
/// run), or in the plane of all of them with neighbours on every side (inside a flat face). Both tests
/// allow the piece's size times kOuterPointTolerance, far below a float's resolution at that size, and
/// keep a point when in doubt. Every corner of the hull is kept (a corner is never inside the hull of
/// other points), so the hull of the kept points is the hull of all of them.

#include "algorithms/core/mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// Distance, relative to the piece's bounding-box diagonal, within which a point counts as on the
/// segment or in the plane of its neighbours.
inline constexpr double kOuterPointTolerance = 1e-9;

/// Each vertex's distinct face planes and neighbours, in flat arrays (no allocation per vertex).
struct VertexPlanes {
  std::vector<std::int32_t> normal_start;  ///< #V + 1 offsets into normals
  std::vector<Vec3> normals;               ///< unit normals; two within ~4.5e-5 rad count as one
  std::vector<std::int32_t> ring_start;    ///< #V + 1 offsets into ring
  std::vector<std::int32_t> ring;          ///< the vertices sharing a face with each vertex (may repeat)

  [[nodiscard]] std::span<const Vec3> normals_of(std::size_t v) const {
    return {normals.data() + normal_start[v], normals.data() + normal_start[v + 1]};
  }
  [[nodiscard]] std::span<const std::int32_t> ring_of(std::size_t v) const {
    return {ring.data() + ring_start[v], ring.data() + ring_start[v + 1]};
  }
};

/// The planes and neighbours of every vertex of `mesh` (degenerate faces give no plane).
[[nodiscard]] VertexPlanes vertex_planes(const Mesh& mesh);

/// Indices, ascending, of the vertices of `mesh` that the tests above do not prove inside the hull of
/// their neighbours; `planes` is vertex_planes(mesh). Vertices on no face are kept.
[[nodiscard]] std::vector<std::int32_t> outer_point_indices(const Mesh& mesh, const VertexPlanes& planes);

}  // namespace shatter
