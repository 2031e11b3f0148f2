#pragma once
/// Internals shared by the cgal-clip translation units: the exact mesh type (CGAL Surface_mesh over
/// Epeck) with its "is_cut" face flag, the corefinement visitor that keeps that flag right, and the
/// conversions between shatter meshes and exact pieces. Includes CGAL: only for files of this folder.
///
/// Attributes (mesh_attributes.h): when the input carries them, every exact face also carries the
/// index of the input triangle it lies in ("f:source", -1 for a cap), kept through every clip and
/// triangulation like "is_cut". A fragment's face then gets its source triangle's corner values at
/// the barycentric coordinates of each exact corner in the exact source triangle (computed exactly,
/// rounded once), and a cap is dressed as a cut face with its exact normal. Without attributes the
/// property does not exist and none of this work is done.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace shatter::cgal_exact {

namespace PMP = CGAL::Polygon_mesh_processing;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Epeck::Point_3;
using ExactPlane = Epeck::Plane_3;
using SurfaceMesh = CGAL::Surface_mesh<ExactPoint>;
using FaceIndex = SurfaceMesh::Face_index;
using VertexIndex = SurfaceMesh::Vertex_index;
using CutMap = SurfaceMesh::Property_map<FaceIndex, bool>;
using SourceMap = SurfaceMesh::Property_map<FaceIndex, std::int32_t>;

/// A step CGAL could not complete; turned into an Error at the fracturer's boundary.
struct ClipFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The "is_cut" flag of every face of `mesh` (created, false, when absent).
inline CutMap cut_map(SurfaceMesh& mesh) { return mesh.add_property_map<FaceIndex, bool>("f:is_cut", false).first; }

/// The "f:source" map of `mesh` (input triangle per face, -1 for a cap) and whether the mesh has it.
inline std::pair<SourceMap, bool> find_source_map(const SurfaceMesh& mesh) {
  return mesh.property_map<FaceIndex, std::int32_t>("f:source");
}

/// The "f:source" map of `mesh` (created, -1, when absent).
inline SourceMap add_source_map(SurfaceMesh& mesh) {
  return mesh.add_property_map<FaceIndex, std::int32_t>("f:source", -1).first;
}

/// The exact plane {x : dot(normal, x - point) = 0} built from the same doubles (no rounding);
/// its negative side is below.
inline ExactPlane exact_plane(const Vec3& point, const Vec3& normal) {
  return {ExactPoint(point.x(), point.y(), point.z()), Epeck::Vector_3(normal.x(), normal.y(), normal.z())};
}

/// The mesh being cut in place and the flag (and source triangle) of the face currently being split.
struct TagState {
  const SurfaceMesh* mesh = nullptr;
  CutMap is_cut;
  bool split_flag = false;
  SourceMap source;              ///< valid when tracks_source
  bool tracks_source = false;    ///< the mesh carries "f:source"
  std::int32_t split_source = -1;
};

/// The state for cutting `mesh` in place: its flag map, and its source map when it has one.
inline TagState tag_state(SurfaceMesh& mesh) {
  TagState state{&mesh, cut_map(mesh)};
  std::tie(state.source, state.tracks_source) = find_source_map(mesh);
  return state;
}

/// Corefinement visitor that keeps "is_cut" right on a mesh cut in place (PMP::clip, or a Boolean
/// operation whose output is its first input): a split face inherits the flag of the face it came
/// from, a face copied from the other operand (the clipper, the cell) is a cut face, untouched faces
/// keep their flag. CGAL copies the visitor, so the state lives outside it.
struct ClipTagVisitor : PMP::Corefinement::Default_visitor<SurfaceMesh> {
  TagState* state = nullptr;

  void before_subface_creations(FaceIndex f_old, SurfaceMesh& tm) {
    if (&tm != state->mesh) return;
    state->split_flag = state->is_cut[f_old];
    if (state->tracks_source) state->split_source = state->source[f_old];
  }
  void after_subface_created(FaceIndex f_new, SurfaceMesh& tm) {
    if (&tm != state->mesh) return;
    state->is_cut[f_new] = state->split_flag;
    if (state->tracks_source) state->source[f_new] = state->split_source;
  }
  void after_face_copy(FaceIndex f_old, const SurfaceMesh& source, FaceIndex f_new, SurfaceMesh& target) {
    if (&target != state->mesh) return;
    const bool own = &source == state->mesh;
    state->is_cut[f_new] = own ? state->is_cut[f_old] : true;
    if (state->tracks_source) state->source[f_new] = own ? state->source[f_old] : -1;
  }
};

/// One connected closed piece: an exact triangle mesh without garbage, with the face property
/// "is_cut" (and "f:source" when the input has attributes), its elements in a canonical order (see
/// append_parts).
struct Piece {
  SurfaceMesh mesh;              ///< triangulated, canonical element order
  Vec3 centroid = Vec3::Zero();  ///< volume centroid, m (cached: orderings ask for it repeatedly)
};

/// The minimal kernel order_parts (recursive_slicing.h) needs to sort pieces.
struct PieceOrder {
  using Piece = cgal_exact::Piece;
  /// Cached volume centroid of `piece`, m.
  [[nodiscard]] Vec3 centroid(const Piece& piece) const { return piece.centroid; }
};

/// Volume centroid of `mesh` by the divergence theorem in double, from exactly rounded positions (the
/// same in every build); the vertex mean when the volume vanishes.
Vec3 centroid_of(const SurfaceMesh& mesh);

/// Appends the volumes of the closed mesh `mesh` (CGAL's volume_connected_components: an outer shell
/// with the cavities inside it) as pieces, each rebuilt in a canonical order
/// (vertices in exact lexicographic order, faces sorted by vertex ranks), so that the output does not
/// depend on the heap addresses CGAL's corefinement breaks ties with. Triangulates polygon faces.
void append_parts(SurfaceMesh&& mesh, std::vector<Piece>& out);

/// `solid` (a mesh that passed check_solid) as one exact mesh (unused vertices dropped, sheets meeting
/// at a pinched vertex given their own vertex, tags kept as "is_cut", and each face's triangle index
/// as "f:source" when `solid` has attributes). CGAL's own self-intersection test stays as an internal
/// assertion: it throws ClipFailure.
SurfaceMesh exact_solid(const Mesh& solid);

/// Converts one piece of `solid` (the mesh given to exact_solid) into a fragment: points rounded from
/// their exact values (the same point gives the same doubles in every fragment; points that round to
/// one double point become one vertex and the triangles between them, of no area, are dropped), the
/// attributes of `solid` carried over (see the file comment), mass properties.
Fragment to_fragment(Piece& piece, const Mesh& solid);

}  // namespace shatter::cgal_exact
