#pragma once
/// Indexed triangle mesh in double precision, the one geometry type every algorithm exchanges.
///
/// Design note: a fragment must say which of its faces came from the input (surface) and which were
/// made by a fracture (cut): metrics compare the surface area against the input, bonds are found on
/// cut faces only, and renderers texture the two differently. Faces that mesh repair added to close an
/// input (algorithms/repair/) carry a third tag, so area metrics compare like with like. The tag is therefore per triangle and
/// travels with the triangle through every slice. Vertices are shared between triangles (indexed),
/// so closedness and orientation are checked on the index structure, not on coordinates. A game
/// asset's normals, UVs, tangents and materials ride along per triangle corner (mesh_attributes.h).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "algorithms/core/mesh_attributes.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace shatter {

/// A point or direction in 3D, metres.
using Vec3 = Eigen::Vector3d;
/// A point in a 2D projection, metres.
using Vec2 = Eigen::Vector2d;
/// Three vertex indices, counter-clockwise seen from outside the solid.
using Triangle = std::array<std::int32_t, 3>;

/// Where a face of a fragment comes from.
enum class FaceTag : std::uint8_t {
  surface = 0,  ///< part of the input mesh's boundary
  cut = 1,      ///< made by a fracture (a cap)
  repair = 2,   ///< added by mesh repair (a filled hole, a wrap), not part of the input's own surface
};

/// Indexed triangle mesh. Invariant: `tags.size() == triangles.size()`, every index < vertices.size(),
/// and `attributes` empty or sized to the triangles (check_attributes). Code that adds triangles to a
/// mesh that may carry attributes goes through attribute_transfer.h, which keeps them in step.
struct Mesh {
  std::vector<Vec3> vertices;        ///< #V positions, m
  std::vector<Triangle> triangles;   ///< #F vertex index triples, outward counter-clockwise
  std::vector<FaceTag> tags;         ///< #F face origins
  MeshAttributes attributes;         ///< per-corner normals, UVs, tangents, per-face materials; usually empty

  /// Number of triangles.
  [[nodiscard]] std::size_t triangle_count() const { return triangles.size(); }
  /// True when the mesh has no triangles.
  [[nodiscard]] bool empty() const { return triangles.empty(); }
  /// Adds a triangle with its tag (no attribute values: for meshes without attributes).
  void add_triangle(std::int32_t a, std::int32_t b, std::int32_t c, FaceTag tag) {
    triangles.push_back({a, b, c});
    tags.push_back(tag);
  }
  /// Adds a vertex and returns its index.
  std::int32_t add_vertex(const Vec3& p) {
    vertices.push_back(p);
    return static_cast<std::int32_t>(vertices.size() - 1);
  }
};

/// Axis-aligned bounding box, m.
struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());   ///< lower corner
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());  ///< upper corner
  /// Grows the box to contain `p`.
  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  /// True when `p` lies inside or on the box.
  [[nodiscard]] bool contains(const Vec3& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
  /// Length of the diagonal, m (0 for an empty box).
  [[nodiscard]] double diagonal() const { return min.x() <= max.x() ? (max - min).norm() : 0.0; }
};

/// Bounding box of the mesh's referenced and unreferenced vertices.
inline Aabb bounding_box(const Mesh& mesh) {
  Aabb box;
  for (const Vec3& p : mesh.vertices) box.extend(p);
  return box;
}

}  // namespace shatter
