#pragma once
/// Nearest-triangle queries on a mesh: which triangle of a mesh a point lies on (or is nearest to).
/// Used to find, for a point on a fragment or on a repaired surface, the input triangle it came from.
///
/// Design note: triangles are binned by bounding box into a uniform grid of about one triangle per
/// cell; a query visits the cells in rings of growing Chebyshev radius around the point's cell and
/// stops once the nearest triangle found is closer than any cell of the next ring can be. The closest
/// point on a triangle is found by the region tests of Ericson, "Real-Time Collision Detection", 5.1.5.

#include "algorithms/core/mesh.h"

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace shatter {

/// The point of triangle (a, b, c) nearest `p`.
[[nodiscard]] Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Barycentric coordinates of `p` projected onto the plane of triangle (a, b, c): weights of a, b, c
/// summing to 1 ((1/3, 1/3, 1/3) for a degenerate triangle).
[[nodiscard]] Vec3 barycentric_coordinates(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Finds the triangle of a mesh nearest a point. Holds a reference to the mesh: the mesh must outlive
/// the locator and not change.
class TriangleLocator {
 public:
  /// Bins the triangles of `mesh` whose entry of `include` is non-zero (every triangle when `include`
  /// is empty).
  explicit TriangleLocator(const Mesh& mesh, std::span<const std::uint8_t> include = {});

  /// A nearest triangle and how far it is.
  struct Hit {
    std::int32_t triangle = -1;                                  ///< -1 when no triangle was binned
    double distance2 = std::numeric_limits<double>::infinity();  ///< squared distance, m^2
  };

  /// The binned triangle nearest `p` (the lowest index among equally near ones).
  [[nodiscard]] Hit nearest(const Vec3& p) const;

 private:
  [[nodiscard]] std::array<int, 3> cell_of(const Vec3& p) const;

  const Mesh* mesh_;
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1.0;
  std::array<int, 3> dims_{0, 0, 0};
  std::vector<std::uint32_t> start_;     // CSR: cell -> first entry in triangles_
  std::vector<std::int32_t> triangles_;  // triangle indices by cell
};

}  // namespace shatter
