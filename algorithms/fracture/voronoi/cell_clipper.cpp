// The clipping half of CellClipper (cell_clipper.h): owners, the triangles near each cell clipped by
// its planes. The caps are built in cell_caps.cpp.
#include "algorithms/fracture/voronoi/cell_clipper.h"

#include "algorithms/core/predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shatter {
namespace {

bool overlaps(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

/// Weights of a crossing made at parameter `t` from the end beyond the plane (`pos`) towards the
/// other (`neg`): the same mix as its position.
CornerWeights mixed_weights(const CornerWeights& pos, const CornerWeights& neg, double t) {
  return {pos[0] + t * (neg[0] - pos[0]), pos[1] + t * (neg[1] - pos[1]), pos[2] + t * (neg[2] - pos[2])};
}

}  // namespace

CellClipper::CellClipper(const Mesh& solid, std::span<const Vec3> sites, const PointInMesh* inside)
    : solid_(&solid),
      vertex_count_(static_cast<std::int32_t>(solid.vertices.size())),
      attributed_(has_attributes(solid)),
      inside_(inside) {
  seen_.assign(solid.vertices.size(), 0);
  side_offset_.assign(solid.vertices.size(), 0);
  seen_out_.assign(solid.vertices.size(), 0);
  out_of_vertex_.assign(solid.vertices.size(), 0);
  find_owners(sites);
  // Owned triangles by site (CSR, index order within a site), mixed ones with their bounds.
  const std::size_t n = solid.triangles.size();
  std::vector<std::int32_t> triangle_owner(n, -1);
  owned_start_.assign(sites.size() + 1, 0);
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = solid.triangles[f];
    const std::int32_t o = owner_[static_cast<std::size_t>(t[0])];
    if (o >= 0 && o == owner_[static_cast<std::size_t>(t[1])] && o == owner_[static_cast<std::size_t>(t[2])]) {
      triangle_owner[f] = o;
      ++owned_start_[static_cast<std::size_t>(o) + 1];
      continue;
    }
    mixed_.push_back(static_cast<std::int32_t>(f));
    Aabb b;
    for (const std::int32_t v : t) b.extend(solid.vertices[static_cast<std::size_t>(v)]);
    mixed_bounds_.push_back(b);
  }
  for (std::size_t k = 1; k < owned_start_.size(); ++k) owned_start_[k] += owned_start_[k - 1];
  owned_.resize(static_cast<std::size_t>(owned_start_.back()));
  std::vector<std::int32_t> fill(owned_start_.begin(), owned_start_.end() - 1);
  for (std::size_t f = 0; f < n; ++f)
    if (triangle_owner[f] >= 0) owned_[static_cast<std::size_t>(fill[static_cast<std::size_t>(triangle_owner[f])]++)] = static_cast<std::int32_t>(f);
}

void CellClipper::find_owners(std::span<const Vec3> sites) {
  // |v - s_i|^2 - |v - s_j|^2 = 2 (s_j - s_i) . (v - (s_i + s_j) / 2): a gap in squared distances far
  // above the round-off of both (relative 1e-15 of (extent + |coordinates|) x extent) and of the
  // rounded midpoint puts v strictly on site i's side of the bisector plane as stored.
  Aabb box = bounding_box(*solid_);
  for (const Vec3& s : sites) box.extend(s);
  const double extent = box.diagonal();
  const double magnitude = box.min.cwiseAbs().cwiseMax(box.max.cwiseAbs()).maxCoeff();
  const double margin = 1e-9 * extent * (extent + magnitude);
  owner_.assign(solid_->vertices.size(), -1);
  for (std::size_t v = 0; v < solid_->vertices.size(); ++v) {
    const Vec3& p = solid_->vertices[v];
    double best = std::numeric_limits<double>::infinity();
    double second = best;
    std::int32_t nearest = -1;
    for (std::size_t k = 0; k < sites.size(); ++k) {
      const double d2 = (p - sites[k]).squaredNorm();
      if (d2 < best) {
        second = best;
        best = d2;
        nearest = static_cast<std::int32_t>(k);
      } else if (d2 < second) {
        second = d2;
      }
    }
    if (second - best > margin) owner_[v] = nearest;
  }
}

bool CellClipper::clip(int site, std::span<const Plane> planes, const CellPolytope& polytope, const Aabb& box,
                       const Aabb& bounds, Mesh& out) {
  if (!polytope.ok) return false;
  site_ = site;
  polytope_ = polytope;
  select_planes(planes, box);
  face_of_plane_.assign(planes_.size(), -1);
  for (std::size_t f = 0; f < polytope_.faces.size(); ++f)
    if (polytope_.faces[f].label >= 0) face_of_plane_[static_cast<std::size_t>(polytope_.faces[f].label)] = static_cast<int>(f);
  if (++stamp_ == 0) {  // the stamps wrapped: forget every old one
    std::fill(seen_.begin(), seen_.end(), 0);
    std::fill(seen_out_.begin(), seen_out_.end(), 0);
    stamp_ = 1;
  }
  sides_.clear();
  points_.clear();
  out_of_point_.clear();
  corner_refs_.assign(polytope_.corners.size(), -1);
  edge_crossings_.clear();
  cap_edges_.resize(planes_.size());
  for (auto& edges : cap_edges_) edges.clear();
  edge_points_.clear();
  out_ = Mesh{};
  // The site's own triangles and the mixed ones near the cell, merged in index order.
  const std::int32_t* owned = owned_.data() + owned_start_[static_cast<std::size_t>(site)];
  const std::int32_t* owned_end = owned_.data() + owned_start_[static_cast<std::size_t>(site) + 1];
  if (attributed_) {
    copy_attribute_frame(*solid_, out_);
    // Room for the owned triangles' corners and some cut ones, so that the copies do not reallocate.
    const auto owned_count = static_cast<std::size_t>(owned_end - owned);
    out_.attributes.corners.reserve((owned_count + owned_count / 4 + 64) * 3 *
                                    static_cast<std::size_t>(solid_->attributes.layout.stride()));
    out_.attributes.materials.reserve(owned_count + owned_count / 4 + 64);
  }
  std::size_t m = 0;
  const auto next_mixed = [&] {
    while (m < mixed_.size() && !overlaps(mixed_bounds_[m], bounds)) ++m;
    return m < mixed_.size() ? mixed_[m] : std::numeric_limits<std::int32_t>::max();
  };
  for (std::int32_t mixed = next_mixed(); owned != owned_end || m < mixed_.size();) {
    if (owned != owned_end && *owned < mixed) {
      copy_triangle(static_cast<std::size_t>(*owned++));
      continue;
    }
    if (!clip_triangle(static_cast<std::size_t>(mixed))) return false;
    ++m;
    mixed = next_mixed();
  }
  for (std::size_t p = 0; p < planes_.size(); ++p)
    if (!cap_edges_[p].empty() && face_of_plane_[p] < 0) return false;  // a cut with no face
  if (!walk_cell_edges() || !settle_corners() || !triangulate_caps()) return false;
  out = std::move(out_);
  return true;
}

void CellClipper::copy_triangle(std::size_t f) {
  const Triangle& t = solid_->triangles[f];
  add_triangle_from(out_, *solid_, f, out_index(t[0]), out_index(t[1]), out_index(t[2]));
}

void CellClipper::select_planes(std::span<const Plane> planes, const Aabb& box) {
  // A plane without a face may still pass within round-off of the cell: keep those too, so that the
  // exact side tests see every plane that could cut (a cut on a plane without a face is refused).
  std::vector<std::int32_t> live;
  for (const CellPolytope::Face& face : polytope_.faces) live.insert(live.end(), face.corners.begin(), face.corners.end());
  std::sort(live.begin(), live.end());  // each corner once (it is on three faces or more)
  live.erase(std::unique(live.begin(), live.end()), live.end());
  std::vector<int> slot(planes.size(), -1);
  for (const CellPolytope::Face& face : polytope_.faces)
    if (face.label >= 0) slot[static_cast<std::size_t>(face.label)] = 0;
  const double tolerance = 1e-9 * box.diagonal();
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (slot[p] == 0) continue;
    const double slack = tolerance * planes[p].normal.norm();
    for (const std::int32_t c : live)
      if (planes[p].normal.dot(polytope_.corners[static_cast<std::size_t>(c)] - planes[p].point) > -slack) {
        slot[p] = 0;
        break;
      }
  }
  planes_.clear();
  for (std::size_t p = 0; p < planes.size(); ++p)
    if (slot[p] == 0) {
      slot[p] = static_cast<int>(planes_.size());
      planes_.push_back(planes[p]);
    }
  const auto relabel = [&](int label) { return label < 0 ? label : slot[static_cast<std::size_t>(label)]; };
  for (CellPolytope::Face& face : polytope_.faces) {
    face.label = relabel(face.label);
    for (int& across : face.across) across = relabel(across);
  }
}

int CellClipper::vertex_side(std::int32_t v, int plane) {
  const auto sv = static_cast<std::size_t>(v);
  if (seen_[sv] != stamp_) first_sight(v);
  return sides_[static_cast<std::size_t>(side_offset_[sv]) + static_cast<std::size_t>(plane)];
}

bool CellClipper::inside_all(std::int32_t v) {
  const auto sv = static_cast<std::size_t>(v);
  if (seen_[sv] != stamp_) first_sight(v);
  return sides_[static_cast<std::size_t>(side_offset_[sv]) + planes_.size()] < 0;
}

void CellClipper::first_sight(std::int32_t v) {
  // All sides at once, then one more entry: -1 when the vertex is strictly inside every plane.
  const auto sv = static_cast<std::size_t>(v);
  seen_[sv] = stamp_;
  side_offset_[sv] = static_cast<std::int32_t>(sides_.size());
  if (owner_[sv] == site_) {  // certainly strictly inside every bisector of the cell
    sides_.insert(sides_.end(), planes_.size() + 1, std::int8_t{-1});
    return;
  }
  std::int8_t all = -1;
  for (const Plane& p : planes_) {
    const auto s = static_cast<std::int8_t>(plane_side(solid_->vertices[sv], p.point, p.normal));
    sides_.push_back(s);
    if (s >= 0) all = 1;
  }
  sides_.push_back(all);
}

int CellClipper::corner_side(const PolygonCorner& c, int plane) {
  if (c.ref < vertex_count_) return vertex_side(c.ref, plane);
  if (c.edge_u >= 0) {
    // A point on a solid edge whose ends are strictly on one side is on that side: decided by the
    // edge alone, so the two triangles of the edge agree even when rounding put it a hair across.
    const int su = vertex_side(c.edge_u, plane);
    const int sw = vertex_side(c.edge_w, plane);
    if (su == sw && su != 0) return su;
  }
  const Plane& p = planes_[static_cast<std::size_t>(plane)];
  return plane_side(position(c.ref), p.point, p.normal);
}

CellClipper::PolygonCorner CellClipper::crossing(const PolygonCorner& a, int side_a, const PolygonCorner& b,
                                                 int plane) {
  const bool on_solid_edge = a.plane < 0;  // the piece a -> b of one of the triangle's own edges
  PolygonCorner x{-1, -1, -1, -1};
  // Interpolate from the end beyond the plane, so that either order of a and b gives the same point.
  const PolygonCorner& pos = side_a > 0 ? a : b;
  const PolygonCorner& neg = side_a > 0 ? b : a;
  if (on_solid_edge) {
    // The solid edge under a -> b: from whichever end was made on it, else the two solid vertices.
    const PolygonCorner& made = a.edge_u >= 0 ? a : b;
    x.edge_u = made.edge_u >= 0 ? made.edge_u : a.ref;
    x.edge_w = made.edge_u >= 0 ? made.edge_w : b.ref;
    if (x.edge_u > x.edge_w) std::swap(x.edge_u, x.edge_w);
    const CrossingKey key{pair_key(std::min(a.ref, b.ref), std::max(a.ref, b.ref)), plane};
    const auto found = edge_crossings_.find(key);
    if (found != edge_crossings_.end()) {
      x.ref = found->second;
      // The point was made from the same two ends (the sides agree), so the same parameter gives
      // its weights in this triangle.
      if (attributed_) x.weights = mixed_weights(pos.weights, neg.weights, crossing_parameter(pos.ref, neg.ref, plane));
      return x;
    }
  }
  const double t = crossing_parameter(pos.ref, neg.ref, plane);
  const Vec3 pp = position(pos.ref);
  const Vec3 pm = position(neg.ref);
  if (attributed_) x.weights = mixed_weights(pos.weights, neg.weights, t);
  x.ref = vertex_count_ + static_cast<std::int32_t>(points_.size());
  points_.push_back(pp + t * (pm - pp));
  out_of_point_.push_back(-1);
  if (on_solid_edge) edge_crossings_.emplace(CrossingKey{pair_key(std::min(a.ref, b.ref), std::max(a.ref, b.ref)), plane}, x.ref);
  return x;
}

double CellClipper::crossing_parameter(std::int32_t pos, std::int32_t neg, int plane) const {
  const Plane& p = planes_[static_cast<std::size_t>(plane)];
  const Vec3& pp = position(pos);
  const Vec3& pm = position(neg);
  const double dp = p.normal.dot(pp - p.point);
  const double dm = p.normal.dot(pm - p.point);
  const double denom = dp - dm;
  return std::clamp(denom > 0 ? dp / denom : 0.5, 0.0, 1.0);
}

bool CellClipper::clip_triangle(std::size_t f) {
  const Triangle& t = solid_->triangles[f];
  polygon_.assign({{t[0], -1}, {t[1], -1}, {t[2], -1}});
  if (attributed_) {
    polygon_[0].weights = {1.0, 0.0, 0.0};
    polygon_[1].weights = {0.0, 1.0, 0.0};
    polygon_[2].weights = {0.0, 0.0, 1.0};
  }
  const bool interior = inside_all(t[0]) && inside_all(t[1]) && inside_all(t[2]);
  for (int m = 0; !interior && m < static_cast<int>(planes_.size()); ++m) {
    const int s0 = vertex_side(t[0], m);
    const int s1 = vertex_side(t[1], m);
    const int s2 = vertex_side(t[2], m);
    if (s0 < 0 && s1 < 0 && s2 < 0) continue;  // the whole triangle is inside this plane
    if (s0 == 0 || s1 == 0 || s2 == 0) return false;
    if (s0 > 0 && s1 > 0 && s2 > 0) return true;  // wholly outside the cell
    clipped_.clear();
    const std::size_t n = polygon_.size();
    int first_side = 0;
    int side_a = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const PolygonCorner& a = polygon_[k];
      const PolygonCorner& b = polygon_[(k + 1) % n];
      if (k == 0) first_side = side_a = corner_side(a, m);
      const int side_b = k + 1 == n ? first_side : corner_side(b, m);
      if (side_a == 0 || side_b == 0) return false;
      if (side_a < 0) clipped_.push_back(a);
      if (side_a != side_b) {
        PolygonCorner x = crossing(a, side_a, b, m);
        x.plane = side_a < 0 ? m : a.plane;
        clipped_.push_back(x);
      }
      side_a = side_b;
    }
    if (clipped_.size() < 3) return true;
    std::swap(polygon_, clipped_);
  }
  const std::size_t n = polygon_.size();
  for (std::size_t k = 1; k + 1 < n; ++k)
    add_triangle_weighted(out_, *solid_, f, out_index(polygon_[0].ref), out_index(polygon_[k].ref),
                          out_index(polygon_[k + 1].ref), {polygon_[0].weights, polygon_[k].weights, polygon_[k + 1].weights});
  for (std::size_t k = 0; k < n; ++k) {
    const PolygonCorner& a = polygon_[k];
    const PolygonCorner& b = polygon_[(k + 1) % n];
    if (a.plane >= 0) cap_edges_[static_cast<std::size_t>(a.plane)].push_back({b.ref, a.ref});
    const int before = polygon_[(k + n - 1) % n].plane;
    if (before >= 0 && a.plane >= 0) {
      // The cell edge between the two planes passes through the triangle here.
      edge_points_.emplace_back(pair_key(std::min(before, a.plane), std::max(before, a.plane)),
                                EdgePoint{a.ref, before, a.plane});
    }
  }
  return true;
}

std::int32_t CellClipper::corner_ref(std::int32_t corner) {
  std::int32_t& ref = corner_refs_[static_cast<std::size_t>(corner)];
  if (ref < 0) {
    ref = vertex_count_ + static_cast<std::int32_t>(points_.size());
    points_.push_back(polytope_.corners[static_cast<std::size_t>(corner)]);
    out_of_point_.push_back(-1);
  }
  return ref;
}

std::int32_t CellClipper::out_index(std::int32_t ref) {
  if (ref < vertex_count_) {
    const auto v = static_cast<std::size_t>(ref);
    if (seen_out_[v] != stamp_) {
      seen_out_[v] = stamp_;
      out_of_vertex_[v] = out_.add_vertex(solid_->vertices[v]);
    }
    return out_of_vertex_[v];
  }
  std::int32_t& index = out_of_point_[static_cast<std::size_t>(ref - vertex_count_)];
  if (index < 0) index = out_.add_vertex(points_[static_cast<std::size_t>(ref - vertex_count_)]);
  return index;
}

}  // namespace shatter
