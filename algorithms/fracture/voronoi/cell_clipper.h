#pragma once
/// Cuts one convex cell out of a closed solid in one pass over the triangles near the cell.
///
/// Design note: cutting a cell out of the solid plane by plane (MeshSlicer) costs one pass over the
/// piece per face and re-cuts every earlier cap. Here each triangle whose bounds meet the cell's
/// bounds is clipped against the cell's planes in a fixed order (Sutherland-Hodgman). Which side a
/// point is on is always an exact predicate on the point as stored; a crossing point on a triangle
/// edge is made once per edge and plane (from the edge's own end points, in a fixed order), so the
/// two triangles of an edge share it and the clipped surface stays watertight. A triangle with all
/// corners on the inside of a plane lies wholly inside it (convexity), so only planes that separate
/// a triangle's corners clip it; triangles strictly inside every plane are copied as they are.
///
/// Each cap (one per face of the cell that meets the solid) is bounded by the clipped triangles'
/// edges on its plane and by the stretches of the face's edges inside the solid. Those stretches
/// end where a clipped triangle has a corner between edges on two planes (the edge of the cell
/// passes through the triangle there); the same point serves both caps of that cell edge, and the
/// inside stretches are found by walking along the edge, so both caps use the same segments. Corners
/// of the cell inside the solid follow from the walks; a cell whose edges never meet the surface is
/// wholly inside or outside, decided by an exact inside test of one corner. Each cap is fanned when
/// it is one convex loop (convex_cap.h), else triangulated by triangulate_cap. Whenever a step cannot
/// be decided consistently (a point exactly on a plane, a corner of four planes, walks that disagree,
/// a cap that does not close), `clip` returns false and writes nothing: the caller then cuts that
/// cell with the sequential slicer.
///
/// Most triangles lie wholly inside one cell. So each solid vertex first gets its owner: the site
/// nearest to it when the next nearest is farther by a margin far above the round-off of squared
/// distances and of the bisector's midpoint, so that the vertex is certainly strictly inside every
/// bisector of that site's cell (the exact side tests would agree). A triangle whose three corners
/// have one owner lies inside that cell (convexity): it is copied into that cell without a side test
/// and never looked at for the others. Only the other triangles ("mixed") are clipped, each by the
/// cells whose bounds meet its bounds; their owned corners need no side test either.
///
/// Attributes (mesh_attributes.h): every polygon corner carries its barycentric weights over the
/// source triangle's corners, mixed at each crossing with the same parameter as its position (a corner
/// may be cut by several planes in turn); a clipped triangle's corner values are those weighted sums,
/// a copied triangle keeps its values, and cap triangles are dressed as cut faces with their plane's
/// normal, which points out of the cell. A solid without attributes takes none of this work.

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/core/cap_triangulator.h"
#include "algorithms/fracture/voronoi/cell_polytope.h"
#include "algorithms/fracture/voronoi/point_in_mesh.h"

#include <absl/container/flat_hash_map.h>

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace shatter {

/// Clips a closed, outward solid to convex cells; keeps scratch buffers between calls.
class CellClipper {
 public:
  /// Finds the owner site of every vertex of `solid` among `sites` (#S, m) and sorts the triangles
  /// into owned and mixed ones, O(#V #S + #F). `solid`, `sites` and `inside` (an inside test of
  /// `solid`, or null to build one on first need) must outlive the clipper.
  CellClipper(const Mesh& solid, std::span<const Vec3> sites, const PointInMesh* inside = nullptr);

  /// Writes into `out` the part of the solid in the cell of site `site`: on the negative side of
  /// every plane of `planes` (the bisectors of `site` with other sites; #P planes), which lies in
  /// `bounds` (m). `polytope` is the cell clipped to a box `box` (m) that holds the solid strictly
  /// inside, face labels indexing `planes`. The part may be empty or have several connected parts.
  /// False (and `out` untouched) when the cell must be cut by the exact sequential path.
  bool clip(int site, std::span<const Plane> planes, const CellPolytope& polytope, const Aabb& box,
            const Aabb& bounds, Mesh& out);

 private:
  /// One corner of a triangle clipped so far: a point ref and the plane of the edge leaving it
  /// (-1 on the triangle's own edges).
  struct PolygonCorner {
    std::int32_t ref;
    int plane;
    std::int32_t edge_u = -1;  ///< the solid edge the point lies on (-1: a solid vertex or inside)
    std::int32_t edge_w = -1;
    CornerWeights weights{};   ///< over the source triangle's corners; only kept for attributed solids
  };
  /// Where a clipped triangle passes a cell edge: the point, the plane whose cap edge starts there
  /// ("out") and the plane whose cap edge ends there ("in").
  struct EdgePoint {
    std::int32_t ref;
    int out_of;
    int into;
  };

  /// (a, b) as one 64-bit key, a in the high half.
  static std::uint64_t pair_key(std::int32_t a, std::int32_t b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }
  void find_owners(std::span<const Vec3> sites);
  void copy_triangle(std::size_t f);
  bool clip_triangle(std::size_t f);
  bool walk_cell_edges();
  bool settle_corners();
  bool triangulate_caps();
  /// Appends cap triangle `t` (slots into `refs`) on plane `plane`, dressed as a cut face.
  void add_cap_triangle(std::size_t plane, const std::vector<std::int32_t>& refs, const Triangle& t);
  void select_planes(std::span<const Plane> planes, const Aabb& box);
  void first_sight(std::int32_t v);
  bool inside_all(std::int32_t v);
  int vertex_side(std::int32_t v, int plane);
  int corner_side(const PolygonCorner& c, int plane);
  PolygonCorner crossing(const PolygonCorner& a, int side_a, const PolygonCorner& b, int plane);
  /// Where plane `plane` crosses the segment from ref `pos` (beyond it) to ref `neg`, in [0, 1].
  double crossing_parameter(std::int32_t pos, std::int32_t neg, int plane) const;
  std::int32_t corner_ref(std::int32_t corner);
  std::int32_t out_index(std::int32_t ref);
  [[nodiscard]] const Vec3& position(std::int32_t ref) const {
    return ref < vertex_count_ ? solid_->vertices[static_cast<std::size_t>(ref)]
                               : points_[static_cast<std::size_t>(ref - vertex_count_)];
  }

  const Mesh* solid_;
  std::int32_t vertex_count_;
  bool attributed_;                                // the solid carries attributes
  std::vector<std::int32_t> owner_;                // per solid vertex: its owner site, -1 when unclear
  std::vector<std::int32_t> owned_start_;          // per site: CSR offsets into owned_, #S + 1
  std::vector<std::int32_t> owned_;                // triangles whose corners share one owner, by site
  std::vector<std::int32_t> mixed_;                // the other triangles, in index order
  std::vector<Aabb> mixed_bounds_;                 // their bounds
  const PointInMesh* inside_;                      // the caller's, or own_inside_ built on first need
  std::unique_ptr<PointInMesh> own_inside_;
  int site_ = -1;                                  // the cell being clipped

  // Per cell. A "ref" names a vertex of the solid (0..V-1) or a made point (V+k).
  std::vector<Plane> planes_;                      // the planes that may cut the cell, in order
  CellPolytope polytope_;
  std::vector<int> face_of_plane_;                 // plane -> face index, -1 without a face
  std::vector<std::uint32_t> seen_;                // per solid vertex: stamp of the cell its sides are for
  std::vector<std::int32_t> side_offset_;          // per solid vertex: offset of its sides in sides_
  std::vector<std::int8_t> sides_;                 // exact sides of solid vertices, #planes + 1 each
  std::uint32_t stamp_ = 0;
  std::vector<Vec3> points_;                       // made points
  std::vector<std::int32_t> corner_refs_;          // polytope corner -> ref, -1 until used
  struct CrossingKey {
    std::uint64_t edge;  // the two refs of a solid edge's piece, smaller first
    int plane;
    bool operator==(const CrossingKey&) const = default;
    template <typename H>
    friend H AbslHashValue(H h, const CrossingKey& k) {
      return H::combine(std::move(h), k.edge, k.plane);
    }
  };
  absl::flat_hash_map<CrossingKey, std::int32_t> edge_crossings_;  // -> ref
  std::vector<std::int32_t> out_of_vertex_;        // solid vertex -> index in out_, valid if seen_out_
  std::vector<std::uint32_t> seen_out_;
  std::vector<std::int32_t> out_of_point_;         // made point -> index in out_, -1 if absent
  std::vector<PolygonCorner> polygon_;
  std::vector<PolygonCorner> clipped_;
  std::vector<std::vector<CapEdge>> cap_edges_;    // per plane, edges over refs
  std::vector<std::uint32_t> cap_stamp_;           // per ref: the cap its cap_slot_ is for
  std::vector<std::int32_t> cap_slot_;             // per ref: its index among the cap's points
  std::uint32_t cap_count_ = 0;                    // caps triangulated so far (the stamps)
  std::vector<std::pair<std::uint64_t, EdgePoint>> edge_points_;  // (cell edge key, point)
  std::vector<std::int8_t> corner_inside_;         // per polytope corner: -1 unknown, 0 out, 1 in
  std::vector<std::pair<std::int32_t, std::int32_t>> free_edges_;  // cell edges no triangle meets
  Mesh out_;
};

}  // namespace shatter
