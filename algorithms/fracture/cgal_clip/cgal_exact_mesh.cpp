#include "algorithms/fracture/cgal_clip/cgal_exact_mesh.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/pinched_vertices.h"

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <map>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

namespace shatter::cgal_exact {
namespace {

/// Triangulation visitor: subfaces inherit the flag (and source triangle) of the polygon they come from.
struct TriangulateTagVisitor {
  CutMap is_cut;
  SourceMap source;            ///< valid when tracks_source
  bool tracks_source = false;  ///< the mesh carries "f:source"
  std::shared_ptr<std::pair<bool, std::int32_t>> split = std::make_shared<std::pair<bool, std::int32_t>>(false, -1);

  void before_subface_creations(FaceIndex f_old) {
    *split = {is_cut[f_old], tracks_source ? source[f_old] : -1};
  }
  void after_subface_created(FaceIndex f_new) {
    is_cut[f_new] = split->first;
    if (tracks_source) source[f_new] = split->second;
  }
  void after_subface_creations() {}
};

using ExactKernel = Epeck::Exact_kernel;
using ExactValue = ExactKernel::FT;
using ExactValuePoint = ExactKernel::Point_3;

/// Position of an exact point rounded from its exact value.
Vec3 rounded(const ExactPoint& p) {
  const auto& e = CGAL::exact(p);
  return {CGAL::to_double(e.x()), CGAL::to_double(e.y()), CGAL::to_double(e.z())};
}

/// Twice the signed area of (a, b, c) projected along axis `drop`, exact.
ExactValue projected_area(const ExactValuePoint& a, const ExactValuePoint& b, const ExactValuePoint& c, int drop) {
  const int i = (drop + 1) % 3;
  const int j = (drop + 2) % 3;
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}

/// Barycentric coordinates over the corners of one input triangle, exact, for points in its plane.
class ExactBarycentric {
 public:
  /// Triangle `f` of `solid`, whose corners are exact as doubles.
  ExactBarycentric(const Mesh& solid, std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = solid.vertices[static_cast<std::size_t>(solid.triangles[f][k])];
      corners_[k] = ExactValuePoint(p.x(), p.y(), p.z());
    }
    // Any axis along which the exact normal has a component gives exact coordinates; the largest
    // one of the rounded normal is non-zero whenever the triangle has an area in doubles.
    const auto normal = CGAL::cross_product(corners_[1] - corners_[0], corners_[2] - corners_[0]);
    double largest = -1.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double n = std::abs(CGAL::to_double(normal[axis]));
      if (normal[axis] != 0 && n > largest) {
        largest = n;
        drop_ = axis;
      }
    }
    if (largest < 0.0) throw ClipFailure("input triangle " + std::to_string(f) + " has no area");
    area_ = projected_area(corners_[0], corners_[1], corners_[2], drop_);
  }

  /// The weights of `p` (a point in the triangle's plane) over corners 0, 1, 2, rounded from exact.
  [[nodiscard]] CornerWeights operator()(const ExactValuePoint& p) const {
    const ExactValue w0 = projected_area(p, corners_[1], corners_[2], drop_) / area_;
    const ExactValue w1 = projected_area(corners_[0], p, corners_[2], drop_) / area_;
    const ExactValue w2 = ExactValue(1) - w0 - w1;
    return {CGAL::to_double(w0), CGAL::to_double(w1), CGAL::to_double(w2)};
  }

 private:
  std::array<ExactValuePoint, 3> corners_;
  int drop_ = 2;
  ExactValue area_;
};

/// The unit normal of the exact triangle (a, b, c), its direction exact up to the final rounding.
Vec3 exact_normal(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  const ExactValuePoint& ea = CGAL::exact(a);
  const auto n = CGAL::cross_product(CGAL::exact(b) - ea, CGAL::exact(c) - ea);
  // Scaled exactly so that its largest component is +-1 before rounding: no underflow for tiny faces.
  ExactValue largest = CGAL::abs(n.x());
  for (const ExactValue& c : {ExactValue(CGAL::abs(n.y())), ExactValue(CGAL::abs(n.z()))})
    if (c > largest) largest = c;
  if (largest == 0) throw ClipFailure("a cut face has no area");
  const ExactValue x = n.x() / largest;
  const ExactValue y = n.y() / largest;
  const ExactValue z = n.z() / largest;
  const Vec3 scaled(CGAL::to_double(x), CGAL::to_double(y), CGAL::to_double(z));
  return scaled.normalized();
}

}  // namespace

// The centroid (the next cut plane's point) is computed from exactly rounded positions, not from the
// points' interval approximations: an interval tightens whenever CGAL happens to need the exact value,
// and builds with CGAL's assertions on need it more often, so cut planes taken from the intervals
// differed between builds.
Vec3 centroid_of(const SurfaceMesh& mesh) {
  Vec3 moment = Vec3::Zero();
  double six_volume = 0.0;
  for (FaceIndex f : mesh.faces()) {
    auto h = mesh.halfedge(f);
    const Vec3 a = rounded(mesh.point(mesh.target(h)));
    // Fan over the face's corners, in case a face is not a triangle.
    for (auto g = mesh.next(h); mesh.target(mesh.next(g)) != mesh.target(h); g = mesh.next(g)) {
      const Vec3 b = rounded(mesh.point(mesh.target(g)));
      const Vec3 c = rounded(mesh.point(mesh.target(mesh.next(g))));
      const double v = a.dot(b.cross(c));
      six_volume += v;
      moment += v * (a + b + c);
    }
  }
  if (six_volume > 0.0 && std::isfinite(six_volume)) return moment / (4.0 * six_volume);
  Vec3 mean = Vec3::Zero();
  for (VertexIndex v : mesh.vertices()) mean += rounded(mesh.point(v));
  return mesh.number_of_vertices() > 0 ? Vec3(mean / static_cast<double>(mesh.number_of_vertices())) : mean;
}

void append_parts(SurfaceMesh&& mesh, std::vector<Piece>& out) {
  CutMap is_cut = cut_map(mesh);
  const auto [source, tracks_source] = find_source_map(mesh);
  if (!CGAL::is_triangle_mesh(mesh)) {
    TriangulateTagVisitor visitor{is_cut, source, tracks_source};
    if (!PMP::triangulate_faces(mesh, CGAL::parameters::visitor(visitor)))
      throw ClipFailure("a face of a piece could not be triangulated");
  }
  if (mesh.has_garbage()) mesh.collect_garbage();
  if (mesh.number_of_faces() == 0) return;

  std::vector<VertexIndex> by_position(mesh.vertices().begin(), mesh.vertices().end());
  std::stable_sort(by_position.begin(), by_position.end(), [&](VertexIndex a, VertexIndex b) {
    return CGAL::compare_xyz(mesh.point(a), mesh.point(b)) == CGAL::SMALLER;
  });
  std::vector<std::uint32_t> rank(mesh.number_of_vertices());
  for (std::size_t i = 0; i < by_position.size(); ++i) rank[by_position[i]] = static_cast<std::uint32_t>(i);

  // Faces as rank triples rotated to start at their smallest rank (orientation kept), sorted.
  struct FaceKey {
    std::array<std::uint32_t, 3> corners;
    std::size_t component;
    FaceIndex face;
  };
  auto component = mesh.add_property_map<FaceIndex, std::size_t>("f:component", 0).first;
  const std::size_t count = PMP::volume_connected_components(mesh, component);
  std::vector<FaceKey> keys;
  keys.reserve(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    std::array<std::uint32_t, 3> r{rank[mesh.source(h)], rank[mesh.target(h)], rank[mesh.target(mesh.next(h))]};
    std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
    keys.push_back({r, component[f], f});
  }
  std::sort(keys.begin(), keys.end(), [](const FaceKey& a, const FaceKey& b) { return a.corners < b.corners; });
  mesh.remove_property_map(component);

  // Parts in the order of their first face; each part's vertices in the order of first use.
  std::vector<std::size_t> part_of_component(count, count);
  std::size_t parts = 0;
  for (const FaceKey& k : keys)
    if (part_of_component[k.component] == count) part_of_component[k.component] = parts++;
  std::vector<SurfaceMesh> meshes(parts);
  std::vector<CutMap> cut_maps;
  std::vector<SourceMap> source_maps;
  for (SurfaceMesh& m : meshes) {
    cut_maps.push_back(cut_map(m));
    if (tracks_source) source_maps.push_back(add_source_map(m));
  }
  std::vector<VertexIndex> new_index(mesh.number_of_vertices(), SurfaceMesh::null_vertex());
  for (const FaceKey& k : keys) {
    const std::size_t p = part_of_component[k.component];
    SurfaceMesh& part = meshes[p];
    std::array<VertexIndex, 3> corners;
    for (int i = 0; i < 3; ++i) {
      const VertexIndex v = by_position[k.corners[i]];
      if (new_index[v] == SurfaceMesh::null_vertex()) new_index[v] = part.add_vertex(mesh.point(v));
      corners[i] = new_index[v];
    }
    const FaceIndex g = part.add_face(corners[0], corners[1], corners[2]);
    if (g == SurfaceMesh::null_face()) throw ClipFailure("a connected part is not 2-manifold");
    cut_maps[p][g] = is_cut[k.face];
    if (tracks_source) source_maps[p][g] = source[k.face];
  }
  for (SurfaceMesh& part : meshes) {
    const Vec3 c = centroid_of(part);
    out.push_back({std::move(part), c});
  }
}

SurfaceMesh exact_solid(const Mesh& input) {
  Mesh solid = input;
  split_pinched_vertices(solid);  // a Surface_mesh vertex has one fan
  SurfaceMesh mesh;
  CutMap is_cut = cut_map(mesh);
  const bool tracks_source = has_attributes(solid);
  SourceMap source;
  if (tracks_source) source = add_source_map(mesh);
  std::vector<VertexIndex> index(solid.vertices.size(), SurfaceMesh::null_vertex());
  const auto vertex = [&](std::int32_t i) {
    if (index[i] == SurfaceMesh::null_vertex()) {
      const Vec3& p = solid.vertices[i];
      index[i] = mesh.add_vertex(ExactPoint(p.x(), p.y(), p.z()));
    }
    return index[i];
  };
  for (std::size_t t = 0; t < solid.triangles.size(); ++t) {
    const Triangle& tri = solid.triangles[t];
    const FaceIndex f = mesh.add_face(vertex(tri[0]), vertex(tri[1]), vertex(tri[2]));
    if (f == SurfaceMesh::null_face())
      throw ClipFailure("input triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) + ", " +
                        std::to_string(tri[1]) + ", " + std::to_string(tri[2]) +
                        ") makes the surface non-manifold: a vertex where two sheets of triangles meet "
                        "at one point cannot be clipped");
    is_cut[f] = solid.tags[t] == FaceTag::cut;
    if (tracks_source) source[f] = static_cast<std::int32_t>(t);
  }
  // Exact clipping of a mesh without self-intersections never makes one, so the input is checked once
  // here instead of at every cut (where the check, on exact constructed points, costs most of the time).
  if (PMP::does_self_intersect(mesh)) throw ClipFailure("the input mesh intersects itself");
  return mesh;
}

Fragment to_fragment(Piece& piece, const Mesh& solid) {
  SurfaceMesh& mesh = piece.mesh;
  CutMap is_cut = cut_map(mesh);
  Fragment fragment;
  Mesh& out = fragment.mesh;
  const bool attributed = has_attributes(solid);
  const auto [source, tracks_source] = find_source_map(mesh);
  if (attributed && !tracks_source) throw ClipFailure("a piece lost the source triangles of its faces");
  if (attributed) copy_attribute_frame(solid, out);
  std::map<std::int32_t, ExactBarycentric> barycentric;  // per source triangle met
  // Exact points closer than a rounding step (a cut through a vertex's immediate neighbourhood) round
  // to one double point: they become one vertex, and the triangles between them, which have no area
  // in doubles, are dropped (collapsing an edge of zero length keeps the surface closed).
  std::vector<std::int32_t> index(mesh.number_of_vertices(), -1);
  std::map<std::array<double, 3>, std::int32_t> vertex_at;
  out.vertices.reserve(mesh.number_of_vertices());
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 p = rounded(mesh.point(v));
    if (!p.allFinite()) throw ClipFailure("a fragment vertex is not finite in double precision");
    const auto [it, inserted] = vertex_at.try_emplace({p.x() + 0.0, p.y() + 0.0, p.z() + 0.0}, -1);
    if (inserted) it->second = out.add_vertex(p);
    index[v] = it->second;
  }
  out.triangles.reserve(mesh.number_of_faces());
  out.tags.reserve(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const std::int32_t a = index[mesh.source(h)], b = index[mesh.target(h)], c = index[mesh.target(mesh.next(h))];
    if (a == b || b == c || c == a) continue;
    const FaceTag tag = is_cut[f] ? FaceTag::cut : FaceTag::surface;
    if (!attributed) {
      out.add_triangle(a, b, c, tag);
      continue;
    }
    const ExactPoint& pa = mesh.point(mesh.source(h));
    const ExactPoint& pb = mesh.point(mesh.target(h));
    const ExactPoint& pc = mesh.point(mesh.target(mesh.next(h)));
    const std::int32_t s = source[f];
    if (s < 0) {  // a cap: its exact normal points out of the piece
      if (tag != FaceTag::cut) throw ClipFailure("a face that no input triangle holds is not a cut face");
      add_cut_triangle(out, a, b, c, exact_normal(pa, pb, pc));
      continue;
    }
    const auto found = barycentric.try_emplace(s, solid, static_cast<std::size_t>(s)).first;
    const ExactBarycentric& weights = found->second;
    add_triangle_weighted(out, solid, static_cast<std::size_t>(s), a, b, c,
                          {weights(CGAL::exact(pa)), weights(CGAL::exact(pb)), weights(CGAL::exact(pc))});
    out.tags.back() = tag;  // as without attributes: "is_cut" decides (a repair face comes out surface)
  }
  // The solid's values were checked; a weighted sum of values near the largest doubles, or a cut
  // face's UV of a position far out against a tiny UV scale, can still overflow (the reference
  // checks its output whatever fracture_attributes_bounded says).
  if (attributed && !all_finite(out.attributes.corners.data(), out.attributes.corners.size()))
    throw ClipFailure(kAttributeOverflow);
  fragment.mass = mass_properties(out);
  return fragment;
}

}  // namespace shatter::cgal_exact
