#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/cgal_clip/cgal_exact_mesh.h"
#include "algorithms/fracture/cgal_clip/exact_convex_polytope.h"

#include "algorithms/core/predicates.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/recursive_slicing.h"

#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <utility>
#include <vector>

// How a cell is applied: the cell's half-spaces clip a box strictly larger than the solid's bounding
// box (ExactConvexPolytope: exact vertices, outward faces), and the solid is intersected with that
// closed convex mesh by one corefinement, PMP::corefine_and_compute_intersection, in place on a copy
// of the exact solid. Clipping the solid plane after plane would corefine it once per plane, each
// time with a box-sized clipper, and make every cap vertex from earlier constructed ones; one Boolean
// operation per cell does the work once. The box's faces lie outside the solid, so every face the
// cell contributes comes from one of its planes and is tagged cut (ClipTagVisitor).
//
// Cells are skipped before any corefinement when their bounding box misses the solid's, or when one
// of their face planes leaves every solid vertex on or above it (exact, plane_side): the intersection
// then has no interior, and asking CGAL for it would be a degenerate case for nothing.

namespace shatter {
namespace {

using namespace cgal_exact;

/// Axis-aligned bounds of the vertices used by `solid`'s triangles, m.
std::array<Vec3, 2> solid_bounds(const Mesh& solid) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<Vec3, 2> box{Vec3::Constant(inf), Vec3::Constant(-inf)};
  for (const Triangle& t : solid.triangles)
    for (std::int32_t v : t) {
      box[0] = box[0].cwiseMin(solid.vertices[v]);
      box[1] = box[1].cwiseMax(solid.vertices[v]);
    }
  return box;
}

/// `bounds` enlarged by a quarter of its diagonal, strictly, whatever the rounding.
std::array<Vec3, 2> enlarged(const std::array<Vec3, 2>& bounds) {
  const double margin = 0.25 * (bounds[1] - bounds[0]).norm() + 1e-300;
  std::array<Vec3, 2> box = bounds;
  for (int i = 0; i < 3; ++i) {
    box[0][i] = bounds[0][i] - margin;
    box[1][i] = bounds[1][i] + margin;
    if (!(box[0][i] < bounds[0][i])) box[0][i] = std::nextafter(bounds[0][i], -std::numeric_limits<double>::infinity());
    if (!(box[1][i] > bounds[1][i])) box[1][i] = std::nextafter(bounds[1][i], std::numeric_limits<double>::infinity());
  }
  if (!box[0].allFinite() || !box[1].allFinite()) throw ClipFailure("the input mesh is too large for its bounding box");
  return box;
}

/// True when the boxes [a0, a1] and [b0, b1] share no point.
bool disjoint(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b) {
  for (int i = 0; i < 3; ++i)
    if (a[1][i] < b[0][i] || b[1][i] < a[0][i]) return true;
  return false;
}

/// True when no used vertex of `solid` lies strictly below `plane` (exact on the doubles given).
bool nothing_below(const Mesh& solid, const std::vector<char>& used, const Plane& plane) {
  for (std::size_t v = 0; v < solid.vertices.size(); ++v)
    if (used[v] && plane_side(solid.vertices[v], plane.point, plane.normal) < 0) return false;
  return true;
}

/// The connected parts of (solid ∩ cell), ordered, appended to `out`.
void fracture_cell(const SurfaceMesh& solid, const std::vector<Plane>& planes, const ExactConvexPolytope& cell,
                   std::vector<Piece>& out) {
  SurfaceMesh part = solid;
  SurfaceMesh clipper = cell.triangle_mesh();
  TagState state = tag_state(part);
  ClipTagVisitor visitor;
  visitor.state = &state;
  if (!PMP::corefine_and_compute_intersection(part, clipper, part, CGAL::parameters::visitor(visitor)))
    throw ClipFailure("the part inside a cell of " + std::to_string(planes.size()) +
                      " planes is not 2-manifold (parts touching at a vertex or edge)");
  std::vector<Piece> parts;
  append_parts(std::move(part), parts);
  order_parts(PieceOrder{}, parts);
  for (Piece& p : parts) out.push_back(std::move(p));
}

}  // namespace

Result<std::vector<Fragment>> CgalClipFracturer::fracture_by_cells(const Mesh& solid,
                                                                   std::span<const ConvexCell> cells) const {
  if (Status s = check_fracture_solid(solid, "cgal-clip", nullptr); !s) return s.error();
  if (Status s = check_reference_size(cells.size(), "cells"); !s) return s.error();
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (Status s = check_planes(cells[c].planes); !s)
      return Error{"cgal-clip: cell " + std::to_string(c) + ": " + s.error().message};
  try {
    const SurfaceMesh exact = exact_solid(solid);
    const std::array<Vec3, 2> bounds = solid_bounds(solid);
    const std::array<Vec3, 2> box = enlarged(bounds);
    std::vector<char> used(solid.vertices.size(), 0);
    for (const Triangle& t : solid.triangles)
      for (std::int32_t v : t) used[v] = 1;

    std::vector<Piece> pieces;
    for (const ConvexCell& cell : cells) {
      ExactConvexPolytope polytope(box[0], box[1]);
      for (std::size_t i = 0; i < cell.planes.size() && !polytope.empty(); ++i)
        polytope.clip(exact_plane(cell.planes[i].point, cell.planes[i].normal), static_cast<int>(i));
      if (polytope.empty() || disjoint(polytope.bounds(), bounds)) continue;
      bool separated = false;
      for (int source : polytope.face_sources())
        if (source >= 0 && nothing_below(solid, used, cell.planes[source])) {
          separated = true;
          break;
        }
      if (!separated) fracture_cell(exact, cell.planes, polytope, pieces);
    }
    std::vector<Fragment> fragments;
    fragments.reserve(pieces.size());
    for (Piece& piece : pieces) fragments.push_back(to_fragment(piece, solid));
    return fragments;
  } catch (const std::exception& e) {
    return Error{std::string("cgal-clip: ") + e.what()};
  }
}

}  // namespace shatter
