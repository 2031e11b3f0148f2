#include "algorithms/repair/autorefine_surface.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_components.h"
#include "algorithms/core/self_intersection.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {
namespace {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<ExactKernel::Point_3>;
using ExactFace = ExactMesh::Face_index;
using ExactOriginMap = ExactMesh::Property_map<ExactFace, std::int32_t>;

/// Autorefinement visitor: the pieces of a split face inherit its origin.
struct OriginVisitor : PMP::Corefinement::Default_visitor<ExactMesh> {
  ExactOriginMap origin;
  std::shared_ptr<std::int32_t> current = std::make_shared<std::int32_t>(-1);

  void before_subface_creations(ExactFace f_old, ExactMesh&) { *current = origin[f_old]; }
  void after_subface_created(ExactFace f_new, ExactMesh&) { origin[f_new] = *current; }
};

ExactMesh to_exact(SurfaceMesh& surface) {
  const OriginMap origin = origin_map(surface);
  ExactMesh exact;
  ExactOriginMap exact_origin = exact.add_property_map<ExactFace, std::int32_t>("f:origin", -1).first;
  std::vector<ExactMesh::Vertex_index> index(surface.number_of_vertices() + surface.number_of_removed_vertices());
  for (SurfaceMesh::Vertex_index v : surface.vertices()) {
    const Point& p = surface.point(v);
    index[v.idx()] = exact.add_vertex(ExactKernel::Point_3(p.x(), p.y(), p.z()));
  }
  for (FaceIndex f : surface.faces()) {
    const auto h = surface.halfedge(f);
    const ExactFace g = exact.add_face(index[surface.source(h).idx()], index[surface.target(h).idx()],
                                       index[surface.target(surface.next(h)).idx()]);
    exact_origin[g] = origin[f];
  }
  return exact;
}

/// The exact mesh rounded to doubles, as a Mesh and the origin of each triangle.
std::pair<Mesh, std::vector<std::int32_t>> rounded(ExactMesh& exact) {
  const ExactOriginMap origin = exact.property_map<ExactFace, std::int32_t>("f:origin").first;
  Mesh mesh;
  std::vector<std::int32_t> origins;
  std::vector<std::int32_t> index(exact.number_of_vertices() + exact.number_of_removed_vertices(), -1);
  for (ExactMesh::Vertex_index v : exact.vertices()) {
    const auto& p = CGAL::exact(exact.point(v));
    index[v.idx()] = mesh.add_vertex(Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  for (ExactFace f : exact.faces()) {
    const auto h = exact.halfedge(f);
    mesh.add_triangle(index[exact.source(h).idx()], index[exact.target(h).idx()],
                      index[exact.target(exact.next(h)).idx()], FaceTag::surface);
    origins.push_back(origin[f]);
  }
  return {std::move(mesh), std::move(origins)};
}

/// True when a triangle's rounded corners are collinear (zero area).
bool has_zero_area_triangle(const Mesh& mesh) {
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    if (CGAL::collinear(Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()), Point(c.x(), c.y(), c.z()))) return true;
  }
  return false;
}

bool has_coincident_vertices(const SurfaceMesh& surface) {
  std::vector<Point> points;
  for (SurfaceMesh::Vertex_index v : surface.vertices())
    if (!surface.is_isolated(v)) points.push_back(surface.point(v));
  std::sort(points.begin(), points.end());
  return std::adjacent_find(points.begin(), points.end()) != points.end();
}

}  // namespace

Autorefinement autorefine_surface(SurfaceMesh& surface) {
  Autorefinement result;
  // The project's rule first: corners at equal positions are shared, so faces split apart at a
  // non-manifold vertex or edge only touch (CGAL's test reports those).
  const Mesh before = to_mesh(surface, {});
  if (!find_self_intersection(before)) return result;
  std::vector<std::pair<FaceIndex, FaceIndex>> pairs;
  PMP::self_intersections(surface, std::back_inserter(pairs));
  result.pairs = static_cast<int>(pairs.size());
  if (pairs.empty()) return result;

  // The corefinement identifies intersection points with vertices by position and fails (even
  // crashes) when two vertices share one; such a surface goes to the fallback.
  if (has_coincident_vertices(surface)) {
    result.resolved = false;
    result.failure = "vertices at equal positions, which the autorefinement cannot take";
    return result;
  }
  ExactMesh exact = to_exact(surface);
  OriginVisitor visitor;
  visitor.origin = exact.property_map<ExactFace, std::int32_t>("f:origin").first;
  result.resolved = false;
  if (!PMP::experimental::autorefine_and_remove_self_intersections(exact, PMP::parameters::visitor(visitor))) {
    result.failure = "autorefinement left intersections it could not remove";
    return result;
  }
  auto [mesh, origins] = rounded(exact);
  if (mesh.empty()) {
    result.failure = "autorefinement removed every face";
    return result;
  }
  // The autorefinement keeps the wrong patches where the surface around an intersection is folded
  // or was open: the union of the parts holds at least the largest part, so much less is a failure.
  double largest = 0.0;
  for (const Mesh& part : connected_components(before)) largest = std::max(largest, std::abs(signed_volume(part)));
  if (std::abs(signed_volume(mesh)) < 0.5 * largest) {
    result.failure = "the autorefinement lost more than half of the largest part's volume";
    return result;
  }
  if (has_zero_area_triangle(mesh)) {
    result.failure = "rounding the autorefined surface made a zero-area triangle";
    return result;
  }
  if (find_self_intersection(mesh)) {
    result.failure = "the autorefined surface intersects itself after rounding";
    return result;
  }
  surface = to_surface(mesh, origins);
  result.resolved = true;
  return result;
}

}  // namespace shatter::repair
