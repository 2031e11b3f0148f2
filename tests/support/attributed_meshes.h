#pragma once
// Meshes with attributes whose right values are known anywhere: UVs that are an affine function of
// position, so the value at any point of a fragment can be checked against the formula itself.

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh.h"

namespace shatter::test {

/// u = 0.7 x + 0.1, v = -0.4 y + 0.3 (set 0); u = 0.25 z - 0.5, v = 0.5 x + 0.2 y (set 1).
inline Vec2 affine_uv(const Vec3& p, int set) {
  return set == 0 ? Vec2(0.7 * p.x() + 0.1, -0.4 * p.y() + 0.3) : Vec2(0.25 * p.z() - 0.5, 0.5 * p.x() + 0.2 * p.y());
}

/// `mesh` with per-corner flat normals, two UV sets from affine_uv, tangents along +x projected into
/// each face (handedness +1), one material slot "brick" on every face, readied by prepare_cut_faces.
inline Mesh with_affine_attributes(Mesh mesh) {
  MeshAttributes& a = mesh.attributes;
  a = MeshAttributes{};
  a.layout = AttributeLayout{.normals = true, .uv_sets = 2, .tangents = true};
  MaterialSlot brick;
  brick.name = "brick";
  brick.base_color = {0.6, 0.25, 0.2, 1.0};
  a.slots = {brick};
  a.materials.assign(mesh.triangles.size(), 0);
  for (const Triangle& t : mesh.triangles) {
    const Vec3& p0 = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3 n = (mesh.vertices[static_cast<std::size_t>(t[1])] - p0)
                       .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - p0)
                       .normalized();
    Vec3 tangent = Vec3::UnitX() - n.x() * n;
    if (tangent.squaredNorm() < 1e-12) tangent = Vec3::UnitY() - n.y() * n;
    tangent.normalize();
    for (const std::int32_t v : t) {
      const Vec3& p = mesh.vertices[static_cast<std::size_t>(v)];
      const Vec2 uv0 = affine_uv(p, 0);
      const Vec2 uv1 = affine_uv(p, 1);
      a.corners.insert(a.corners.end(), {n.x(), n.y(), n.z(), uv0.x(), uv0.y(), uv1.x(), uv1.y(), tangent.x(),
                                         tangent.y(), tangent.z(), 1.0});
    }
  }
  prepare_cut_faces(mesh, 0.5);
  return mesh;
}

}  // namespace shatter::test
