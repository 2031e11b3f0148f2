#include "algorithms/repair/repair_surface.h"


namespace shatter::repair {

Mesh to_mesh(SurfaceMesh& surface, const std::vector<FaceTag>& input_tags, std::vector<std::int32_t>* origins) {
  const OriginMap origin = origin_map(surface);
  Mesh mesh;
  if (origins != nullptr) origins->clear();
  std::vector<std::int32_t> index(surface.number_of_vertices() + surface.number_of_removed_vertices(), -1);
  mesh.vertices.reserve(surface.number_of_vertices());
  for (SurfaceMesh::Vertex_index v : surface.vertices()) {
    if (surface.is_isolated(v)) continue;
    const Point& p = surface.point(v);
    index[v.idx()] = mesh.add_vertex(Vec3(p.x(), p.y(), p.z()));
  }
  mesh.triangles.reserve(surface.number_of_faces());
  mesh.tags.reserve(surface.number_of_faces());
  for (FaceIndex f : surface.faces()) {
    const auto h = surface.halfedge(f);
    const std::int32_t a = index[surface.target(h).idx()];
    const std::int32_t b = index[surface.target(surface.next(h)).idx()];
    const std::int32_t c = index[surface.source(h).idx()];
    const std::int32_t from = origin[f];
    const bool tagged = from >= 0 && static_cast<std::size_t>(from) < input_tags.size();
    if (origins != nullptr) origins->push_back(from);
    mesh.add_triangle(c, a, b, tagged ? input_tags[static_cast<std::size_t>(from)] : from >= 0 ? FaceTag::surface : FaceTag::repair);
  }
  return mesh;
}

SurfaceMesh to_surface(const Mesh& mesh, const std::vector<std::int32_t>& origins) {
  SurfaceMesh surface;
  surface.reserve(mesh.vertices.size(), mesh.triangles.size() * 3 / 2, mesh.triangles.size());
  for (const Vec3& p : mesh.vertices) surface.add_vertex(Point(p.x(), p.y(), p.z()));
  OriginMap origin = origin_map(surface);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const FaceIndex f = surface.add_face(SurfaceMesh::Vertex_index(tri[0]), SurfaceMesh::Vertex_index(tri[1]),
                                         SurfaceMesh::Vertex_index(tri[2]));
    if (f != SurfaceMesh::null_face()) origin[f] = origins[t];
  }
  return surface;
}

}  // namespace shatter::repair
