#pragma once
/// The slicing kernel: one closed mesh, one plane, two closed meshes.
///
/// Design note: topology is decided by predicates (which side of the plane each vertex is on: exact,
/// but a vertex within a snap distance of the plane is on it), geometry is then constructed in double
/// (the crossing points). Every edge that crosses
/// the plane gets one crossing point shared by both triangles on it, so both halves stay closed by
/// construction. Faces lying in the plane go to the side they bound (their normal points away from
/// it). The cut's outline is not traced as loops: it is the set of half-edges of the lower half that
/// lie in the plane and have no twin there, which is exactly the boundary the cap must close, however
/// many loops, holes, nested loops or touching loops it has. The cap is one constrained Delaunay
/// triangulation of that outline in an axis-aligned projection (exact: no rotation of coordinates),
/// used as is for the lower half and reversed for the upper half.
///
/// Rounding: the crossings are rounded, so a later cut near an earlier cut's points meets outline
/// points that coincide (merged, in both halves, into one: the ulp-long edges between them collapse)
/// and outlines that run out and straight back (folds, closed by flat cap triangles:
/// outline_folds.h). The first snap distance (16 ulps of the largest coordinate) makes a plane
/// through an earlier cap a miss; when a cut still cannot be capped, or a repair left a half open, it
/// is tried with the wider snaps. Every attempt that snapped, merged or unfolded has its halves checked
/// closed (and for self-intersection, which a wider snap may avoid). docs/plugins.md ("The cutting
/// kernel") states the guarantees and the measured cost.
///
/// Attributes (mesh_attributes.h): a corner at a crossing gets its triangle's two corner values mixed
/// at the parameter its position was made with, measured from the edge's positive end as the position
/// is; cap triangles are dressed as cut faces (attribute_transfer.h). A tracked piece (recursive
/// cuts, corner_provenance.h) records the same mixes instead of evaluating them. A mesh without
/// attributes takes none of these steps.
///
/// The slicer keeps scratch buffers between calls; one slicer per thread.

#include "algorithms/core/corner_provenance.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/fracture/plane_slice/cap_closure.h"
#include "algorithms/fracture/plane_slice/outline_folds.h"
#include "algorithms/core/cap_triangulator.h"

#include <absl/container/flat_hash_map.h>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace shatter {

/// What one slice did.
enum class SliceOutcome {
  cut,         ///< both halves non-empty
  all_below,   ///< the plane does not cut the mesh; nothing written
  all_above,   ///< the plane does not cut the mesh; nothing written
  failed,      ///< the cut outline could not be capped (outline edges crossing
               ///< after rounding); nothing written, so a caller never gets an open half
};

/// What the planes of a call did to the pieces they met: every plane meets every piece once.
struct CutTally {
  int cuts = 0;    ///< a piece split in two
  int misses = 0;  ///< a piece wholly on one side (its vertices within the snap distance count as on the plane)
  int failed = 0;  ///< a piece crossed whose cut could not be capped (left whole or refused, as the caller says)
  int widened = 0; ///< cuts (of `cuts`) made only with a wider snap than the first (MeshSlicer::kSnapRelative)
  int self_intersecting = 0;  ///< cuts (of `cuts`) whose halves cross themselves at rounding scale (MeshSlicer)
};

/// Splits closed meshes by planes.
class MeshSlicer {
 public:
  /// Slices closed, outward `mesh` by `plane`: `below` receives the closed part where
  /// dot(normal, x - point) < 0, `above` the rest; both are overwritten only when the result is `cut`.
  /// Triangles keep their tags and attributes; cap triangles are tagged FaceTag::cut.
  /// With `provenance`, `mesh` is one of its tracked pieces (corner_provenance.h) and so are the halves:
  /// a face passed on whole keeps its record, a cut face and a cap face get new records.
  SliceOutcome slice(const Mesh& mesh, const Plane& plane, Mesh& below, Mesh& above,
                     CornerProvenance* provenance = nullptr);

  /// Which snap distance the last slice was settled with (an index into kSnapRelative: 0 unless a
  /// fallback was needed).
  [[nodiscard]] std::size_t snap_level() const { return snap_level_; }

  /// Whether the halves of the last cut intersect themselves at rounding scale: closed, with the
  /// volume and partition exact, but two faces crossing within an ulp where points were snapped or
  /// merged (no snap distance did better). Such a half is refused as input by the acceptance rule.
  [[nodiscard]] bool self_intersecting() const { return self_intersecting_; }

  /// Snap distances, relative to the largest coordinate of the mesh sliced: a vertex this near the
  /// plane is on it. The first (16 ulps) takes the rounded points of an earlier cut in the same plane
  /// as on it, so that cutting there again is a no-op rather than a shower of slivers; the wider
  /// ones (about 1e-12 and 2e-10 of the size) are tried, in order, only when the narrower one gave an
  /// outline that could not be capped or halves that are not sound.
  static constexpr std::array<double, 3> kSnapRelative = {0x1p-48, 0x1p-40, 0x1p-32};

  /// Why the last slice failed (empty unless it returned `failed`).
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  /// One slice with the vertices within `snap` of the plane taken as on it.
  SliceOutcome attempt(const Mesh& mesh, const Plane& plane, Mesh& below, Mesh& above,
                       CornerProvenance* provenance, double snap, bool merge);
  /// Whether two cap points share a position (sorts cap_order_).
  bool has_coinciding_points();
  /// Whether the halves of an attempt that snapped, merged or unfolded are closed (error_ says why
  /// not); sets self_intersecting_.
  bool halves_are_closed(const Mesh& below, const Mesh& above);
  enum Side : int { below_side = 0, above_side = 1 };
  std::int32_t crossing(std::int32_t a, std::int32_t b);
  std::int32_t index_in(Side side, std::int32_t ref);
  [[nodiscard]] std::array<CornerMix, 3> corner_mixes(std::size_t f, std::int32_t r0, std::int32_t r1,
                                                      std::int32_t r2) const;
  void make_crossings(std::size_t f);
  void merge_coinciding_outline_points();
  [[nodiscard]] std::int32_t canonical(std::int32_t ref) const {
    return merged_ ? canonical_[static_cast<std::size_t>(ref)] : ref;
  }
  void emit(Side side, std::size_t f, std::int32_t r0, std::int32_t r1, std::int32_t r2);
  void split_triangle(std::size_t f);
  bool add_cap();
  [[nodiscard]] bool on_plane(std::int32_t ref) const {
    return ref >= vertex_count_ || side_[static_cast<std::size_t>(ref)] == 0;
  }
  [[nodiscard]] const Vec3& position(std::int32_t ref) const {
    return ref < vertex_count_ ? mesh_->vertices[static_cast<std::size_t>(ref)]
                               : crossing_points_[static_cast<std::size_t>(ref - vertex_count_)];
  }

  // Per-slice state. A "ref" names a vertex of the sliced mesh (0..V-1) or a crossing point (V+k).
  const Mesh* mesh_ = nullptr;
  Plane plane_;
  Mesh* halves_[2] = {nullptr, nullptr};
  std::int32_t vertex_count_ = 0;
  std::vector<std::int8_t> side_;                       // per vertex: -1, 0, +1 (exact)
  std::vector<std::int32_t> index_[2];                  // per ref: index in each half, -1 if absent
  std::vector<Vec3> crossing_points_;                   // per crossing ref - V
  /// Where a crossing's position came from: p + t (m - p), p the edge's end on the positive side.
  struct CrossingEnds {
    std::int32_t p;
    std::int32_t m;
    double t;
  };
  std::vector<CrossingEnds> crossing_ends_;             // per crossing ref - V
  bool attributed_ = false;                             // the sliced mesh carries attributes
  CornerProvenance* provenance_ = nullptr;              // set when the mesh is a tracked piece
  // Lookups only: open addressing (no node allocated per entry).
  absl::flat_hash_map<std::uint64_t, std::int32_t> crossing_of_edge_;  // undirected edge -> ref
  // Iterated, and its order numbers the cap's points: a std::unordered_map, whose order is the same
  // on every run (absl's hash is seeded per process).
  std::unordered_map<std::uint64_t, int> outline_;      // lower half's in-plane half-edges, net count
  std::vector<std::int32_t> cap_ref_;                   // cap point -> ref
  absl::flat_hash_map<std::int32_t, std::int32_t> cap_point_of_ref_;  // lookups only
  std::vector<Vec2> cap_points_;
  std::vector<CapEdge> cap_edges_;
  std::vector<CapEdge> unfolded_edges_;                 // cap_edges_ with folds taken off (outline_folds.h)
  /// An outline point (a vertex on the plane or a crossing) at its projected position.
  struct OutlinePoint {
    Vec2 at;
    std::int32_t ref;
  };
  std::vector<OutlinePoint> merge_order_;               // outline points sorted by position
  std::vector<std::int32_t> cap_order_;                 // cap points sorted by position
  bool merged_ = false;                                 // some outline points were merged this attempt
  bool coinciding_ = false;                             // the attempt failed on coinciding outline points
  bool irregular_ = false;                              // this attempt snapped, merged or unfolded: halves checked
  std::size_t snap_level_ = 0;
  bool self_intersecting_ = false;                      // the halves cross themselves at rounding scale
  std::vector<std::int32_t> canonical_;                 // per ref: the ref it is merged into (when merged_)
  HalfEdgeCounts cap_halfedges_;  // scratch of cap_closes_outline (cap_closure.h)
  std::string error_;
};

}  // namespace shatter
