#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/recursive_slicing.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// How a cut is done: PMP::clip(mesh, plane, clip_volume(true)) keeps the closed part on the negative
// side of the plane. It is run twice per cut, on two copies, once with the plane and once with its
// opposite, so both sides come out closed with their caps (PMP::split would leave them open, and
// closing them again would need a separate hole filling that knows nothing about the plane). The
// clipper is the bounding box cut by the plane, built with the kernel's exact constructions, so each
// cap lies exactly in the requested plane. Epeck is required: with inexact constructions, recursive
// clipping produces self-intersecting pieces that later clips refuse.
//
// Face tags travel as a face property "is_cut" on the Surface_mesh, maintained by a corefinement
// visitor: a face split by the clip inherits the flag of the face it came from, a face copied from the
// clipper (the cap) is a cut face, untouched faces keep their flag.

namespace shatter {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Epeck::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<ExactPoint>;
using FaceIndex = SurfaceMesh::Face_index;
using VertexIndex = SurfaceMesh::Vertex_index;
using CutMap = SurfaceMesh::Property_map<FaceIndex, bool>;

/// A cut that CGAL could not complete; turned into an Error at the fracturer's boundary.
struct ClipFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The "is_cut" flag of every face of `mesh` (created, false, when absent).
CutMap cut_map(SurfaceMesh& mesh) { return mesh.add_property_map<FaceIndex, bool>("f:is_cut", false).first; }

/// The mesh being clipped and the flag of the face currently being split.
struct TagState {
  const SurfaceMesh* mesh = nullptr;
  CutMap is_cut;
  bool split_flag = false;
};

/// Corefinement visitor that keeps "is_cut" right on the clipped mesh. CGAL copies the visitor, so
/// the state lives outside it.
struct ClipTagVisitor : PMP::Corefinement::Default_visitor<SurfaceMesh> {
  TagState* state = nullptr;

  void before_subface_creations(FaceIndex f_old, SurfaceMesh& tm) {
    if (&tm == state->mesh) state->split_flag = state->is_cut[f_old];
  }
  void after_subface_created(FaceIndex f_new, SurfaceMesh& tm) {
    if (&tm == state->mesh) state->is_cut[f_new] = state->split_flag;
  }
  void after_face_copy(FaceIndex f_old, const SurfaceMesh& source, FaceIndex f_new, SurfaceMesh& target) {
    if (&target != state->mesh) return;
    // Faces coming from the clipper are the cap.
    state->is_cut[f_new] = &source == state->mesh ? state->is_cut[f_old] : true;
  }
};

/// Triangulation visitor: subfaces inherit the flag of the polygon they come from.
struct TriangulateTagVisitor {
  CutMap is_cut;
  std::shared_ptr<bool> flag = std::make_shared<bool>(false);

  void before_subface_creations(FaceIndex f_old) { *flag = is_cut[f_old]; }
  void after_subface_created(FaceIndex f_new) { is_cut[f_new] = *flag; }
  void after_subface_creations() {}
};

/// Rounded position of an exact point from its interval approximation (accurate to round-off; cheap).
/// The interval tightens once CGAL has needed the exact value, so this depends on what was computed
/// before; the order of computation is fixed, so it is still deterministic.
Vec3 approximate(const ExactPoint& p) {
  const auto& a = p.approx();
  return {CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z())};
}

/// Position of an exact point rounded from its exact value: the same point gives the same doubles in
/// every fragment that shares it.
Vec3 rounded(const ExactPoint& p) {
  const auto& e = CGAL::exact(p);
  return {CGAL::to_double(e.x()), CGAL::to_double(e.y()), CGAL::to_double(e.z())};
}

/// Volume centroid by the divergence theorem over the (triangulated) faces, in double; the vertex
/// mean when the volume vanishes.
Vec3 centroid_of(const SurfaceMesh& mesh) {
  Vec3 moment = Vec3::Zero();
  double six_volume = 0.0;
  for (FaceIndex f : mesh.faces()) {
    auto h = mesh.halfedge(f);
    const Vec3 a = approximate(mesh.point(mesh.target(h)));
    // Fan over the face's corners, in case a face is not a triangle.
    for (auto g = mesh.next(h); mesh.target(mesh.next(g)) != mesh.target(h); g = mesh.next(g)) {
      const Vec3 b = approximate(mesh.point(mesh.target(g)));
      const Vec3 c = approximate(mesh.point(mesh.target(mesh.next(g))));
      const double v = a.dot(b.cross(c));
      six_volume += v;
      moment += v * (a + b + c);
    }
  }
  if (six_volume > 0.0 && std::isfinite(six_volume)) return moment / (4.0 * six_volume);
  Vec3 mean = Vec3::Zero();
  for (VertexIndex v : mesh.vertices()) mean += approximate(mesh.point(v));
  return mesh.number_of_vertices() > 0 ? Vec3(mean / static_cast<double>(mesh.number_of_vertices())) : mean;
}

/// The slicing kernel of recursive_slicing.h over exact CGAL clipping.
class ExactClipKernel {
 public:
  /// One connected closed piece: an exact mesh without garbage, with the face property "is_cut".
  struct Piece {
    SurfaceMesh mesh;              ///< triangulated, canonical element order (see append_parts)
    Vec3 centroid = Vec3::Zero();  ///< cached: the schedule asks for it repeatedly
  };

  /// Volume centroid of the piece, m (from double approximations; accurate to round-off).
  [[nodiscard]] Vec3 centroid(const Piece& piece) const { return piece.centroid; }

  /// Appends the closed connected parts of `piece` below (dot(normal, x - point) < 0) and above the
  /// plane; appends nothing when the plane leaves the whole piece on one side.
  void split(const Piece& piece, const Plane& plane, std::vector<Piece>& below,
             std::vector<Piece>& above) const {
    const Epeck::Plane_3 cut(ExactPoint(plane.point.x(), plane.point.y(), plane.point.z()),
                             Epeck::Vector_3(plane.normal.x(), plane.normal.y(), plane.normal.z()));
    // Exact side test first: a plane that leaves every vertex on one side (or on it) does not cut the
    // piece in two, and clipping such a touching plane is a degenerate case better not asked of CGAL.
    bool any_below = false;
    bool any_above = false;
    for (VertexIndex v : piece.mesh.vertices()) {
      const CGAL::Oriented_side side = cut.oriented_side(piece.mesh.point(v));
      any_below = any_below || side == CGAL::ON_NEGATIVE_SIDE;
      any_above = any_above || side == CGAL::ON_POSITIVE_SIDE;
      if (any_below && any_above) break;
    }
    if (!any_below || !any_above) return;
    clip_into(piece.mesh, cut, below);
    clip_into(piece.mesh, cut.opposite(), above);
  }

  /// Appends the connected parts of `mesh` (closed) as pieces, each rebuilt in a canonical order.
  ///
  /// CGAL's corefinement numbers new vertices and faces in an order that depends on heap addresses
  /// (its box intersection breaks ties by box address), so the same cut can come out with its
  /// elements permuted. The result's geometry does not depend on it (the triangulations of split faces
  /// are constrained Delaunay with symbolic perturbation), so every piece is rebuilt with vertices in
  /// exact lexicographic order and faces sorted by their vertex ranks: the next centroid, the next
  /// cut and the output are then the same on every run.
  static void append_parts(SurfaceMesh&& mesh, std::vector<Piece>& out) {
    CutMap is_cut = cut_map(mesh);
    if (!CGAL::is_triangle_mesh(mesh)) {
      TriangulateTagVisitor visitor{is_cut};
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
    const std::size_t count = PMP::connected_components(mesh, component);
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
    for (SurfaceMesh& m : meshes) cut_maps.push_back(cut_map(m));
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
    }
    for (SurfaceMesh& part : meshes) {
      const Vec3 c = centroid_of(part);
      out.push_back({std::move(part), c});
    }
  }

 private:
  /// Clips a copy of `mesh` to the negative side of `plane` and appends its parts.
  static void clip_into(const SurfaceMesh& mesh, const Epeck::Plane_3& plane, std::vector<Piece>& out) {
    SurfaceMesh part = mesh;
    TagState state{&part, cut_map(part)};
    ClipTagVisitor visitor;
    visitor.state = &state;
    const bool manifold =
        PMP::clip(part, plane, CGAL::parameters::clip_volume(true).visitor(visitor));
    if (!manifold) throw ClipFailure("a clip gave a non-manifold result (parts touching at a vertex or edge)");
    append_parts(std::move(part), out);
  }
};

/// The input solid as exact pieces (its connected parts; unused vertices dropped); input tags are
/// kept, so a fragment fractured again keeps its earlier cut faces tagged cut.
std::vector<ExactClipKernel::Piece> start_pieces(const Mesh& solid) {
  SurfaceMesh mesh;
  CutMap is_cut = cut_map(mesh);
  std::vector<VertexIndex> index;
  index.reserve(solid.vertices.size());
  for (const Vec3& p : solid.vertices) index.push_back(mesh.add_vertex(ExactPoint(p.x(), p.y(), p.z())));
  for (std::size_t t = 0; t < solid.triangles.size(); ++t) {
    const Triangle& tri = solid.triangles[t];
    const FaceIndex f = mesh.add_face(index[tri[0]], index[tri[1]], index[tri[2]]);
    if (f == SurfaceMesh::null_face())
      throw ClipFailure("input triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) + ", " +
                        std::to_string(tri[1]) + ", " + std::to_string(tri[2]) +
                        ") makes the surface non-manifold: a vertex where two sheets of triangles meet "
                        "at one point cannot be clipped");
    is_cut[f] = solid.tags[t] == FaceTag::cut;
  }
  // PMP::clip requires a mesh without self-intersections. Exact clipping of such a mesh never makes
  // one, so the input is checked once here instead of at every cut (where the check, on exact
  // constructed points, costs most of the time).
  if (PMP::does_self_intersect(mesh)) throw ClipFailure("the input mesh intersects itself");
  std::vector<ExactClipKernel::Piece> pieces;
  ExactClipKernel::append_parts(std::move(mesh), pieces);
  return pieces;
}

/// Converts one exact piece (triangulated by append_parts) into a fragment: points rounded, mass
/// properties.
Fragment to_fragment(ExactClipKernel::Piece& piece) {
  SurfaceMesh& mesh = piece.mesh;
  CutMap is_cut = cut_map(mesh);
  Fragment fragment;
  Mesh& out = fragment.mesh;
  std::vector<std::int32_t> index(mesh.number_of_vertices(), -1);
  out.vertices.reserve(mesh.number_of_vertices());
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 p = rounded(mesh.point(v));
    if (!p.allFinite()) throw ClipFailure("a fragment vertex is not finite in double precision");
    index[v] = out.add_vertex(p);
  }
  out.triangles.reserve(mesh.number_of_faces());
  out.tags.reserve(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    out.add_triangle(index[mesh.source(h)], index[mesh.target(h)], index[mesh.target(mesh.next(h))],
                     is_cut[f] ? FaceTag::cut : FaceTag::surface);
  }
  fragment.mass = mass_properties(out);
  return fragment;
}

/// Checks the boundary input shared by both entry points.
Status check_solid(const Mesh& solid) {
  if (solid.empty()) return Error{"cgal-clip: the input mesh has no triangles"};
  if (solid.tags.size() != solid.triangles.size())
    return Error{"cgal-clip: the input mesh has " + std::to_string(solid.tags.size()) + " tags for " +
                 std::to_string(solid.triangles.size()) + " triangles"};
  for (const Vec3& p : solid.vertices)
    if (!p.allFinite()) return Error{"cgal-clip: the input mesh has a non-finite vertex"};
  const auto vertex_count = static_cast<std::int64_t>(solid.vertices.size());
  for (const Triangle& t : solid.triangles)
    for (std::int32_t i : t)
      if (i < 0 || i >= vertex_count) return Error{"cgal-clip: the input mesh has a vertex index out of range"};
  return {};
}

/// Runs `schedule` on the exact pieces of `solid` and converts the result; CGAL failures become errors.
template <class Schedule>
Result<std::vector<Fragment>> run(const Mesh& solid, Schedule&& schedule) {
  if (Status s = check_solid(solid); !s) return s.error();
  try {
    std::vector<ExactClipKernel::Piece> pieces = schedule(ExactClipKernel{}, start_pieces(solid));
    std::vector<Fragment> fragments;
    fragments.reserve(pieces.size());
    for (ExactClipKernel::Piece& piece : pieces) fragments.push_back(to_fragment(piece));
    return fragments;
  } catch (const std::exception& e) {
    return Error{std::string("cgal-clip: ") + e.what()};
  }
}

}  // namespace

Result<std::vector<Fragment>> CgalClipFracturer::fracture(const Mesh& solid, const FractureParams& params) const {
  if (Status s = check_fracture_params(params); !s) return s.error();
  return run(solid, [&](const ExactClipKernel& kernel, std::vector<ExactClipKernel::Piece> start) {
    return slice_recursively(kernel, std::move(start), params.fragments, params.seed);
  });
}

Result<std::vector<Fragment>> CgalClipFracturer::fracture_by_planes(const Mesh& solid,
                                                                    std::span<const Plane> planes) const {
  if (Status s = check_planes(planes); !s) return s.error();
  return run(solid, [&](const ExactClipKernel& kernel, std::vector<ExactClipKernel::Piece> start) {
    return slice_by_planes(kernel, std::move(start), planes);
  });
}

void register_cgal_clip(FracturerRegistry& registry) {
  registry.add("cgal-clip", "the plane-slice cut schedule done by exact CGAL clipping (reference, slow)",
               [] { return std::make_unique<CgalClipFracturer>(); });
}

}  // namespace shatter
