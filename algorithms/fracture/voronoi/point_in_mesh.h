#pragma once
/// Exact inside test of points against a closed mesh, cheap to build (used to place Voronoi sites).
///
/// Design note: the generalized winding number (winding_number.h) is the project's reference inside
/// test, but its tree costs more to build than a whole Voronoi fracture of a 10k-triangle mesh. Sites
/// are random points we choose, so a cheaper exact test that may answer "undecided" is enough: cast a
/// ray from the point towards +z and count the triangles it crosses, signed by their facing. Triangles
/// are binned in a uniform grid over the xy projection, so a query visits one column of the grid.
/// Every decision is an exact predicate (orient2d on the projection, orient3d for above/below); a ray
/// that touches an edge, a vertex or a vertical face, or a point on a face, makes the query
/// `undecided` and the caller draws another point. For a closed outward mesh the signed count is the
/// winding number: 1 inside, 0 outside.

#include "algorithms/core/mesh.h"

#include <cstdint>
#include <vector>

namespace shatter {

/// Result of one inside query.
enum class InsideAnswer {
  outside,     ///< winding number 0 (or <= 0)
  inside,      ///< winding number >= 1
  undecided,   ///< the ray touches an edge, vertex or vertical face, or the point is on the surface
};

/// Signed ray-crossing inside test over a closed mesh (#F triangles, O(#F) to build).
class PointInMesh {
 public:
  /// Bins the triangles of `mesh` (closed, outward) in about #F / 2 grid columns.
  explicit PointInMesh(const Mesh& mesh);
  /// Where `q` (m) lies relative to the mesh; exact, `undecided` on degenerate rays.
  [[nodiscard]] InsideAnswer operator()(const Vec3& q) const;
  /// Bounding box of the mesh, m.
  [[nodiscard]] const Aabb& bounds() const { return bounds_; }

 private:
  [[nodiscard]] int column(double x, double y) const;
  [[nodiscard]] int column_x(double x) const;
  [[nodiscard]] int column_y(double y) const;
  const Mesh* mesh_;
  Aabb bounds_;
  int nx_ = 1, ny_ = 1;
  double cell_x_ = 1.0, cell_y_ = 1.0;           // m per column
  double inverse_x_ = 1.0, inverse_y_ = 1.0;     // columns per m
  std::vector<std::int32_t> column_start_;       // CSR offsets, nx * ny + 1
  std::vector<std::int32_t> column_triangles_;   // triangle indices per column
};

}  // namespace shatter
