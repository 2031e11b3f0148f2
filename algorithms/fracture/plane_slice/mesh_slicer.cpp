#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/axis_projection.h"

#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/predicates.h"
#include "algorithms/core/self_intersection.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shatter {
namespace {

std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// Projected points in x-then-y order: equal positions end up next to each other.
bool position_before(const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); }

}  // namespace

SliceOutcome MeshSlicer::slice(const Mesh& mesh, const Plane& plane, Mesh& below, Mesh& above,
                               CornerProvenance* provenance) {
  double magnitude = 0.0;
  for (const Vec3& v : mesh.vertices) magnitude = std::max(magnitude, v.cwiseAbs().maxCoeff());
  // Nearest first: a wider snap is tried only when the narrower one gave an outline that could not
  // be capped or halves that are not sound. Halves that are closed but intersect themselves at
  // rounding scale are kept in `below` and `above` while a wider snap is tried, and returned when no
  // snap does better.
  std::string first_error;
  std::size_t closed_level = kSnapRelative.size();
  for (snap_level_ = 0; snap_level_ < kSnapRelative.size(); ++snap_level_) {
    const double snap = kSnapRelative[snap_level_] * magnitude;
    SliceOutcome outcome = attempt(mesh, plane, below, above, provenance, snap, false);
    // Outline points that coincide: again, merging them (an extra pass the usual cut does not pay).
    if (outcome == SliceOutcome::failed && coinciding_) outcome = attempt(mesh, plane, below, above, provenance, snap, true);
    if (outcome == SliceOutcome::cut && self_intersecting_) {
      if (closed_level == kSnapRelative.size()) closed_level = snap_level_;
      // Later attempts write `below` and `above` only when they succeed.
      continue;
    }
    if (outcome != SliceOutcome::failed) {
      self_intersecting_ = false;
      return outcome;
    }
    if (first_error.empty()) first_error = error_;
  }
  if (closed_level < kSnapRelative.size()) {
    snap_level_ = closed_level;
    self_intersecting_ = true;
    error_.clear();
    return SliceOutcome::cut;
  }
  error_ = first_error + "; the same with every wider snap distance, up to 2^-32 of the largest coordinate: " + error_;
  return SliceOutcome::failed;
}

SliceOutcome MeshSlicer::attempt(const Mesh& mesh, const Plane& plane, Mesh& below, Mesh& above,
                                 CornerProvenance* provenance, double snap, bool merge) {
  error_.clear();
  irregular_ = false;
  coinciding_ = false;
  mesh_ = &mesh;
  provenance_ = provenance;
  plane_ = plane;
  vertex_count_ = static_cast<std::int32_t>(mesh.vertices.size());
  side_.resize(mesh.vertices.size());
  int positive = 0;
  int negative = 0;
  const double snap_dot = snap * plane.normal.norm();  // the distance as a value of dot(normal, x - point)
  bool snapped = false;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const int s = plane_side_snapped(mesh.vertices[v], plane.point, plane.normal, snap_dot, snapped);
    side_[v] = static_cast<std::int8_t>(s);
    positive += s > 0;
    negative += s < 0;
  }
  // A vertex taken as on the plane that is not exactly on it: the halves are checked (halves_are_closed).
  irregular_ = snapped;
  if (positive == 0) return SliceOutcome::all_below;
  if (negative == 0) return SliceOutcome::all_above;

  Mesh halves[2];
  halves_[below_side] = &halves[below_side];
  halves_[above_side] = &halves[above_side];
  for (auto& index : index_) index.assign(mesh.vertices.size(), -1);
  crossing_points_.clear();
  crossing_ends_.clear();
  crossing_of_edge_.clear();
  attributed_ = has_attributes(mesh);
  outline_.clear();
  for (Mesh* half : halves_) {
    if (attributed_) {
      copy_attribute_frame(mesh, *half);
      half->attributes.corners.reserve(mesh.attributes.corners.size() / 2 + 48 * mesh.attributes.layout.stride());
      half->attributes.materials.reserve(mesh.attributes.materials.size() / 2 + 16);
    }
    half->vertices.reserve(mesh.vertices.size() / 2 + 16);
    half->triangles.reserve(mesh.triangles.size() / 2 + 16);
    half->tags.reserve(mesh.triangles.size() / 2 + 16);
  }

  merged_ = false;
  if (merge) {
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) make_crossings(f);
    merge_coinciding_outline_points();
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) split_triangle(f);
  if (!add_cap()) return SliceOutcome::failed;
  self_intersecting_ = false;
  if (irregular_ && !halves_are_closed(halves[below_side], halves[above_side])) return SliceOutcome::failed;

  below = std::move(halves[below_side]);
  above = std::move(halves[above_side]);
  return SliceOutcome::cut;
}

bool MeshSlicer::halves_are_closed(const Mesh& below, const Mesh& above) {
  // A repair of rounding (a snapped vertex, merged points, a fold) can meet a configuration it does
  // not settle, such as crossings of different edges rounded onto each other across a gap of the
  // outline: the attempt fails rather than pass on an open half. Points moved by an ulp can also make
  // two faces of a half cross at rounding scale: noted, so that a wider snap is tried for better.
  if (!is_closed_and_oriented(below) || !is_closed_and_oriented(above)) {
    error_ = "a half is not closed after snapping or merging near the plane";
    return false;
  }
  self_intersecting_ = find_self_intersection(below).has_value() || find_self_intersection(above).has_value();
  return true;
}

std::int32_t MeshSlicer::crossing(std::int32_t a, std::int32_t b) {
  const std::uint64_t key = edge_key(std::min(a, b), std::max(a, b));
  const auto found = crossing_of_edge_.find(key);
  if (found != crossing_of_edge_.end()) return found->second;
  // Interpolate from the positive end so that both triangles of the edge get the same point.
  const std::int32_t p = side_[static_cast<std::size_t>(a)] > 0 ? a : b;
  const std::int32_t m = p == a ? b : a;
  const Vec3& pp = mesh_->vertices[static_cast<std::size_t>(p)];
  const Vec3& pm = mesh_->vertices[static_cast<std::size_t>(m)];
  const double dp = plane_.normal.dot(pp - plane_.point);
  const double dm = plane_.normal.dot(pm - plane_.point);
  const double denom = dp - dm;
  double t = denom > 0 ? dp / denom : 0.5;  // the exact signs say dp > 0 > dm; round-off may not
  t = std::clamp(t, 0.0, 1.0);
  const std::int32_t ref = vertex_count_ + static_cast<std::int32_t>(crossing_points_.size());
  crossing_points_.push_back(pp + t * (pm - pp));
  crossing_ends_.push_back({p, m, t});
  index_[below_side].push_back(-1);
  index_[above_side].push_back(-1);
  crossing_of_edge_.emplace(key, ref);
  return ref;
}

std::int32_t MeshSlicer::index_in(Side side, std::int32_t ref) {
  std::int32_t& idx = index_[side][static_cast<std::size_t>(ref)];
  if (idx < 0) idx = halves_[side]->add_vertex(position(ref));
  return idx;
}

std::array<CornerMix, 3> MeshSlicer::corner_mixes(std::size_t f, std::int32_t r0, std::int32_t r1,
                                                  std::int32_t r2) const {
  // Each corner as a mix of the source triangle's corners, at the parameter of its position.
  const Triangle& source = mesh_->triangles[f];
  const auto corner_of = [&](std::int32_t v) { return v == source[0] ? 0 : v == source[1] ? 1 : 2; };
  const auto mix_of = [&](std::int32_t ref) -> CornerMix {
    if (ref < vertex_count_) {
      const int k = corner_of(ref);
      return {k, k, 0.0};
    }
    const CrossingEnds& e = crossing_ends_[static_cast<std::size_t>(ref - vertex_count_)];
    return {corner_of(e.p), corner_of(e.m), e.t};
  };
  return {mix_of(r0), mix_of(r1), mix_of(r2)};
}

void MeshSlicer::make_crossings(std::size_t f) {
  const Triangle& t = mesh_->triangles[f];
  for (int k = 0; k < 3; ++k) {
    const std::int32_t a = t[k];
    const std::int32_t b = t[(k + 1) % 3];
    if (side_[static_cast<std::size_t>(a)] * side_[static_cast<std::size_t>(b)] < 0) crossing(a, b);
  }
}

void MeshSlicer::merge_coinciding_outline_points() {
  // The outline's points: the vertices on the plane and every crossing. Two of them at one projected
  // position (a cut within rounding distance of an earlier cut's vertex, or crossings rounded onto each
  // other) are one point of the cap; the triangulation needs them merged, and the halves too, or the
  // cap would not close them.
  const AxisProjection proj(plane_.normal);
  const auto ref_count = static_cast<std::size_t>(vertex_count_) + crossing_points_.size();
  merged_ = false;
  merge_order_.clear();
  for (std::int32_t v = 0; v < vertex_count_; ++v)
    if (side_[static_cast<std::size_t>(v)] == 0) merge_order_.push_back({proj(position(v)), v});
  for (std::size_t k = 0; k < crossing_points_.size(); ++k)
    merge_order_.push_back({proj(crossing_points_[k]), vertex_count_ + static_cast<std::int32_t>(k)});
  std::sort(merge_order_.begin(), merge_order_.end(), [](const OutlinePoint& a, const OutlinePoint& b) {
    return position_before(a.at, b.at) || (a.at == b.at && a.ref < b.ref);
  });
  for (std::size_t i = 1; i < merge_order_.size(); ++i) {
    if (merge_order_[i].at != merge_order_[i - 1].at) continue;
    if (!merged_) {
      canonical_.resize(ref_count);
      std::iota(canonical_.begin(), canonical_.end(), 0);
      merged_ = true;
      irregular_ = true;
    }
    // Runs of equal points all map to the run's first (lowest) ref, so the choice is the same on every run.
    canonical_[static_cast<std::size_t>(merge_order_[i].ref)] = canonical_[static_cast<std::size_t>(merge_order_[i - 1].ref)];
  }
}

bool MeshSlicer::has_coinciding_points() {
  cap_order_.resize(cap_points_.size());
  std::iota(cap_order_.begin(), cap_order_.end(), 0);
  const auto at = [&](std::int32_t i) -> const Vec2& { return cap_points_[static_cast<std::size_t>(i)]; };
  std::sort(cap_order_.begin(), cap_order_.end(), [&](std::int32_t a, std::int32_t b) { return position_before(at(a), at(b)); });
  for (std::size_t i = 1; i < cap_order_.size(); ++i)
    if (at(cap_order_[i]) == at(cap_order_[i - 1])) return true;
  return false;
}

void MeshSlicer::emit(Side side, std::size_t f, std::int32_t r0, std::int32_t r1, std::int32_t r2) {
  // Indices and the outline take the merged points; attributes are mixed for the points as made.
  const std::int32_t c0 = canonical(r0);
  const std::int32_t c1 = canonical(r1);
  const std::int32_t c2 = canonical(r2);
  if (c0 == c1 || c1 == c2 || c2 == c0) return;  // collapsed by a merge: no area, and its edges cancel
  if (!attributed_) {
    halves_[side]->add_triangle(index_in(side, c0), index_in(side, c1), index_in(side, c2), mesh_->tags[f]);
  } else if (provenance_ != nullptr) {
    const Triangle& source = mesh_->triangles[f];
    std::int32_t record = mesh_->attributes.materials[f];
    if (r0 != source[0] || r1 != source[1] || r2 != source[2]) {
      // Cut: a new record of how each corner mixes the parent's, unless the parent is a cap (a piece
      // of a cap is still a cap of the same plane).
      if (!CornerProvenance::is_cap(record)) record = provenance_->mixed(record, corner_mixes(f, r0, r1, r2));
    }
    Mesh& half = *halves_[side];
    half.add_triangle(index_in(side, c0), index_in(side, c1), index_in(side, c2), mesh_->tags[f]);
    half.attributes.materials.push_back(record);
  } else if (const Triangle& source = mesh_->triangles[f]; r0 == source[0] && r1 == source[1] && r2 == source[2]) {
    // A triangle wholly on one side: copied with its corners as they are.
    add_triangle_from(*halves_[side], *mesh_, f, index_in(side, c0), index_in(side, c1), index_in(side, c2));
  } else {
    add_triangle_mixed(*halves_[side], *mesh_, f, index_in(side, c0), index_in(side, c1), index_in(side, c2),
                       corner_mixes(f, r0, r1, r2));
  }
  if (side != below_side) return;
  // Record the lower half's in-plane half-edges; twins cancel, the rest is the cut outline.
  const std::int32_t r[3] = {c0, c1, c2};
  for (int k = 0; k < 3; ++k) {
    const std::int32_t a = r[k];
    const std::int32_t b = r[(k + 1) % 3];
    if (!on_plane(a) || !on_plane(b)) continue;
    const auto twin = outline_.find(edge_key(b, a));
    if (twin != outline_.end() && twin->second > 0) {
      if (--twin->second == 0) outline_.erase(twin);
    } else {
      ++outline_[edge_key(a, b)];
    }
  }
}

void MeshSlicer::split_triangle(std::size_t f) {
  const Triangle& t = mesh_->triangles[f];
  const int s[3] = {side_[static_cast<std::size_t>(t[0])], side_[static_cast<std::size_t>(t[1])],
                    side_[static_cast<std::size_t>(t[2])]};
  const int positive = (s[0] > 0) + (s[1] > 0) + (s[2] > 0);
  const int negative = (s[0] < 0) + (s[1] < 0) + (s[2] < 0);
  if (negative == 0 && positive > 0) return emit(above_side, f, t[0], t[1], t[2]);
  if (positive == 0 && negative > 0) return emit(below_side, f, t[0], t[1], t[2]);
  if (positive == 0 && negative == 0) {
    // In the plane: the face bounds the side its normal points away from.
    const AxisProjection proj(plane_.normal);
    const Vec3* p[3] = {&mesh_->vertices[static_cast<std::size_t>(t[0])],
                        &mesh_->vertices[static_cast<std::size_t>(t[1])],
                        &mesh_->vertices[static_cast<std::size_t>(t[2])]};
    const int facing = orient2d(proj(*p[0]), proj(*p[1]), proj(*p[2]));
    return emit(facing >= 0 ? below_side : above_side, f, t[0], t[1], t[2]);
  }
  const auto side_of = [&](int k) { return s[k] > 0 ? above_side : below_side; };
  if (positive + negative == 2) {
    // One corner on the plane: split along the segment from it to the opposite edge's crossing.
    int z = 0;
    while (s[z] != 0) ++z;
    const std::int32_t a = t[z];
    const std::int32_t b = t[(z + 1) % 3];
    const std::int32_t c = t[(z + 2) % 3];
    const std::int32_t x = crossing(b, c);
    emit(side_of((z + 1) % 3), f, a, b, x);
    emit(side_of((z + 2) % 3), f, a, x, c);
    return;
  }
  // One corner alone on its side: a triangle there, a quad (two triangles) on the other.
  int lone = 0;
  if (s[1] != s[2] && s[1] != s[0]) lone = 1;
  if (s[2] != s[0] && s[2] != s[1]) lone = 2;
  const std::int32_t a = t[lone];
  const std::int32_t b = t[(lone + 1) % 3];
  const std::int32_t c = t[(lone + 2) % 3];
  const std::int32_t xab = crossing(a, b);
  const std::int32_t xac = crossing(a, c);
  const Side lone_side = side_of(lone);
  const Side other_side = lone_side == above_side ? below_side : above_side;
  emit(lone_side, f, a, xab, xac);
  emit(other_side, f, xab, b, c);
  emit(other_side, f, xab, c, xac);
}

bool MeshSlicer::add_cap() {
  const AxisProjection proj(plane_.normal);
  cap_ref_.clear();
  cap_points_.clear();
  cap_edges_.clear();
  cap_point_of_ref_.clear();
  const auto cap_point = [&](std::int32_t ref) {
    const auto [it, inserted] = cap_point_of_ref_.try_emplace(ref, static_cast<std::int32_t>(cap_ref_.size()));
    if (inserted) {
      cap_ref_.push_back(ref);
      cap_points_.push_back(proj(position(ref)));
    }
    return it->second;
  };
  for (const auto& [key, count] : outline_) {
    const auto a = static_cast<std::int32_t>(key >> 32);
    const auto b = static_cast<std::int32_t>(key & 0xffffffffu);
    // The cap closes the lower half: its edges run opposite to the outline.
    for (int i = 0; i < count; ++i) cap_edges_.push_back({cap_point(b), cap_point(a)});
  }
  if (cap_edges_.empty()) return true;
  if (!merged_ && has_coinciding_points()) {
    // Two outline points at one position (a cut within rounding distance of an earlier cut's vertex,
    // or crossings rounded onto each other): the caller tries again, merging them.
    coinciding_ = true;
    error_ = "two points of the cut outline coincide after rounding";
    return false;
  }
  const std::vector<Triangle> folds = remove_outline_folds(cap_points_, cap_edges_, unfolded_edges_);
  if (!folds.empty()) irregular_ = true;
  const std::vector<CapEdge>& edges = folds.empty() ? cap_edges_ : unfolded_edges_;
  CapTriangulation cap;
  if (!edges.empty()) cap = triangulate_cap(cap_points_, edges);
  cap.triangles.insert(cap.triangles.end(), folds.begin(), folds.end());
  if (!cap.ok) {
    error_ = "cap triangulation failed: " + cap.error;
    return false;
  }
  if (!cap_closes_outline(cap.triangles, cap_edges_, cap_halfedges_)) {
    error_ = "the cap triangulation does not close the cut outline";
    return false;
  }
  if (provenance_ != nullptr) {
    // Tracked pieces: the cap faces carry the record of their side's plane, dressed at the end.
    // The lower half's caps face along the normal (below_side is 0), the upper half's against it.
    const std::array<std::int32_t, 2> record = provenance_->caps(plane_.normal);
    for (const Triangle& t : cap.triangles) {
      const std::int32_t r0 = cap_ref_[static_cast<std::size_t>(t[0])];
      const std::int32_t r1 = cap_ref_[static_cast<std::size_t>(t[1])];
      const std::int32_t r2 = cap_ref_[static_cast<std::size_t>(t[2])];
      halves_[below_side]->add_triangle(index_in(below_side, r0), index_in(below_side, r1),
                                        index_in(below_side, r2), FaceTag::cut);
      halves_[above_side]->add_triangle(index_in(above_side, r0), index_in(above_side, r2),
                                        index_in(above_side, r1), FaceTag::cut);
      halves_[below_side]->attributes.materials.push_back(record[below_side]);
      halves_[above_side]->attributes.materials.push_back(record[above_side]);
    }
    return true;
  }
  for (const Triangle& t : cap.triangles) {
    const std::int32_t r0 = cap_ref_[static_cast<std::size_t>(t[0])];
    const std::int32_t r1 = cap_ref_[static_cast<std::size_t>(t[1])];
    const std::int32_t r2 = cap_ref_[static_cast<std::size_t>(t[2])];
    // The lower half's cap faces the positive side, the upper half's the negative side.
    add_cut_triangle(*halves_[below_side], index_in(below_side, r0), index_in(below_side, r1),
                     index_in(below_side, r2), plane_.normal);
    add_cut_triangle(*halves_[above_side], index_in(above_side, r0), index_in(above_side, r2),
                     index_in(above_side, r1), -plane_.normal);
  }
  return true;
}

}  // namespace shatter
