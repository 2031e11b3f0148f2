#include "algorithms/core/mesh_assembly.h"

#include "algorithms/core/attribute_transfer.h"

#include <cstddef>
#include <cstdint>
#include <utility>

namespace shatter {

void append_mesh(Mesh& into, const Mesh& part) {
  if (into.triangles.empty() && !part.attributes.empty()) copy_attribute_frame(part, into);
  const auto offset = static_cast<std::int32_t>(into.vertices.size());
  into.vertices.insert(into.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (std::size_t f = 0; f < part.triangles.size(); ++f) {
    const Triangle& t = part.triangles[f];
    add_triangle_from(into, part, f, t[0] + offset, t[1] + offset, t[2] + offset);
  }
}

Mesh reversed_mesh(Mesh mesh) {
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  reverse_corner_order(mesh);
  return mesh;
}

Mesh triangle_soup(const Mesh& mesh) {
  Mesh out;
  copy_attribute_frame(mesh, out);
  out.vertices.reserve(mesh.triangles.size() * 3);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const std::int32_t a = out.add_vertex(mesh.vertices[static_cast<std::size_t>(t[0])]);
    const std::int32_t b = out.add_vertex(mesh.vertices[static_cast<std::size_t>(t[1])]);
    const std::int32_t c = out.add_vertex(mesh.vertices[static_cast<std::size_t>(t[2])]);
    add_triangle_from(out, mesh, f, a, b, c);
  }
  return out;
}

}  // namespace shatter
