#include "algorithms/core/surface_mapping.h"

#include <cmath>

namespace shatter {

void apply_box_mapping(Mesh& mesh, double uv_scale, const MaterialSlot& material) {
  MeshAttributes& attr = mesh.attributes;
  attr = MeshAttributes{};
  attr.layout = AttributeLayout{.normals = true, .uv_sets = 1, .tangents = true};
  attr.slots = {material};
  attr.materials.assign(mesh.triangles.size(), 0);
  attr.corners.reserve(mesh.triangles.size() * 3 * static_cast<std::size_t>(attr.layout.stride()));
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    Vec3 n = (b - a).cross(c - a);
    n = n.squaredNorm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitZ();
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(n[i]) > std::abs(n[axis])) axis = i;
    const double s = n[axis] >= 0.0 ? 1.0 : -1.0;
    // Right and up seen from outside the face (right x up = the projection axis, outward).
    Vec3 right;
    Vec3 up;
    if (axis == 0) {
      right = Vec3(0.0, s, 0.0);
      up = Vec3::UnitZ();
    } else if (axis == 1) {
      right = Vec3(-s, 0.0, 0.0);
      up = Vec3::UnitZ();
    } else {
      right = Vec3(s, 0.0, 0.0);
      up = Vec3::UnitY();
    }
    // The tangent is +u within the face's plane; the bitangent's handedness follows +v.
    Vec3 tangent = right - right.dot(n) * n;
    tangent = tangent.squaredNorm() > 0.0 ? Vec3(tangent.normalized()) : Vec3(up.cross(n).normalized());
    const double w = n.cross(tangent).dot(up) >= 0.0 ? 1.0 : -1.0;
    for (const Vec3* p : {&a, &b, &c}) {
      attr.corners.insert(attr.corners.end(), {n.x(), n.y(), n.z(), p->dot(right) / uv_scale, p->dot(up) / uv_scale,
                                               tangent.x(), tangent.y(), tangent.z(), w});
    }
  }
}

}  // namespace shatter
