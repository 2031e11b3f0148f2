// The cap half of CellClipper (cell_clipper.h): the walks along the cell's edges, the corners inside
// the solid, and the triangulation of each cap. The clipping of the triangles is in cell_clipper.cpp.
#include "algorithms/core/axis_projection.h"
#include "algorithms/fracture/plane_slice/cap_closure.h"
#include "algorithms/fracture/plane_slice/convex_cap.h"
#include "algorithms/fracture/voronoi/cell_clipper.h"

#include <algorithm>

namespace shatter {

bool CellClipper::walk_cell_edges() {
  corner_inside_.assign(polytope_.corners.size(), -1);
  free_edges_.clear();
  const auto settle = [&](std::int32_t corner, bool inside) {
    std::int8_t& s = corner_inside_[static_cast<std::size_t>(corner)];
    if (s >= 0 && s != static_cast<std::int8_t>(inside)) return false;
    s = static_cast<std::int8_t>(inside);
    return true;
  };
  // Points along each cell edge, sorted by the edge (smaller plane first) and then along the edge's
  // direction on the smaller plane's face: normal(a) x normal(b).
  std::vector<std::pair<double, std::size_t>> order;
  std::sort(edge_points_.begin(), edge_points_.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::size_t matched = 0;
  for (const CellPolytope::Face& face : polytope_.faces) {
    const int a = face.label;
    const std::size_t n = face.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int b = face.across[k];
      const std::int32_t s = face.corners[k];
      const std::int32_t e = face.corners[(k + 1) % n];
      if (a > b) continue;  // each edge once, from the face with the smaller label
      if (a < 0 || b < 0) {   // the box lies outside the solid: no triangle meets these edges
        free_edges_.emplace_back(s, e);
        continue;
      }
      const std::uint64_t key = pair_key(a, b);
      const auto lo = std::lower_bound(edge_points_.begin(), edge_points_.end(), key,
                                       [](const auto& x, std::uint64_t k2) { return x.first < k2; });
      auto hi = lo;
      while (hi != edge_points_.end() && hi->first == key) ++hi;
      if (lo == hi) {
        free_edges_.emplace_back(s, e);
        continue;
      }
      matched += static_cast<std::size_t>(hi - lo);
      const Vec3 direction = planes_[static_cast<std::size_t>(a)].normal.cross(planes_[static_cast<std::size_t>(b)].normal);
      order.clear();
      for (auto it = lo; it != hi; ++it)
        order.emplace_back(direction.dot(position(it->second.ref)), static_cast<std::size_t>(it - edge_points_.begin()));
      std::sort(order.begin(), order.end());
      const auto emit = [&](std::int32_t p, std::int32_t q) {
        cap_edges_[static_cast<std::size_t>(a)].push_back({p, q});
        cap_edges_[static_cast<std::size_t>(b)].push_back({q, p});
      };
      // An inside stretch of the edge starts where a cap edge of face a ends, and ends where one starts.
      bool inside = edge_points_[order.front().second].second.out_of == a;
      if (!settle(s, inside)) return false;
      std::int32_t start = inside ? corner_ref(s) : -1;
      for (const auto& [t, index] : order) {
        const EdgePoint& x = edge_points_[index].second;
        if (x.into == a) {
          if (inside) return false;
          inside = true;
          start = x.ref;
        } else {
          if (!inside) return false;
          emit(start, x.ref);
          inside = false;
        }
      }
      if (inside) emit(start, corner_ref(e));
      if (!settle(e, inside)) return false;
    }
  }
  return matched == edge_points_.size();  // every point lies on an edge of the polytope
}

bool CellClipper::settle_corners() {
  // Edges that no triangle meets have the same state at both ends: spread the known states.
  bool changed = true;
  bool any_known = std::any_of(corner_inside_.begin(), corner_inside_.end(), [](std::int8_t s) { return s >= 0; });
  if (!any_known) {
    // No cell edge meets the surface: the cell is wholly inside or wholly outside the solid.
    bool on_box = false;
    for (const CellPolytope::Face& face : polytope_.faces) on_box |= face.label < 0;
    bool inside = false;
    if (!on_box) {
      if (inside_ == nullptr) {
        own_inside_ = std::make_unique<PointInMesh>(*solid_);
        inside_ = own_inside_.get();
      }
      const InsideAnswer answer = (*inside_)(polytope_.corners[static_cast<std::size_t>(polytope_.faces.front().corners.front())]);
      if (answer == InsideAnswer::undecided) return false;
      inside = answer == InsideAnswer::inside;
    }
    std::fill(corner_inside_.begin(), corner_inside_.end(), static_cast<std::int8_t>(inside));
  }
  while (changed) {
    changed = false;
    for (const auto& [s, e] : free_edges_) {
      std::int8_t& a = corner_inside_[static_cast<std::size_t>(s)];
      std::int8_t& b = corner_inside_[static_cast<std::size_t>(e)];
      if (a >= 0 && b >= 0 && a != b) return false;
      if (a >= 0 && b < 0) b = a, changed = true;
      if (b >= 0 && a < 0) a = b, changed = true;
    }
  }
  for (const CellPolytope::Face& face : polytope_.faces) {
    const std::size_t n = face.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::int32_t s = face.corners[k];
      const std::int8_t state = corner_inside_[static_cast<std::size_t>(s)];
      if (state < 0) return false;
      if (state == 1 && face.label < 0) return false;  // the box lies outside the solid
      const int b = face.across[k];
      if (state == 1 && b >= 0 && face.label < b) {
        const std::int32_t e = face.corners[(k + 1) % n];
        const bool free = std::find(free_edges_.begin(), free_edges_.end(), std::make_pair(s, e)) != free_edges_.end();
        if (free) {  // a whole edge inside the solid: it bounds both caps
          cap_edges_[static_cast<std::size_t>(face.label)].push_back({corner_ref(s), corner_ref(e)});
          cap_edges_[static_cast<std::size_t>(b)].push_back({corner_ref(e), corner_ref(s)});
        }
      }
    }
  }
  return true;
}

void CellClipper::add_cap_triangle(std::size_t plane, const std::vector<std::int32_t>& refs, const Triangle& t) {
  // The cell lies on the negative side of each of its planes: the normal points out of the fragment.
  add_cut_triangle(out_, out_index(refs[static_cast<std::size_t>(t[0])]), out_index(refs[static_cast<std::size_t>(t[1])]),
                   out_index(refs[static_cast<std::size_t>(t[2])]), planes_[plane].normal);
}

bool CellClipper::triangulate_caps() {
  std::vector<std::int32_t> refs;
  std::vector<Vec2> points;
  std::vector<CapEdge> edges;
  std::vector<std::int32_t> order;
  HalfEdgeCounts halfedges;
  std::vector<Triangle> fan;
  const std::size_t ref_count = static_cast<std::size_t>(vertex_count_) + points_.size();
  if (cap_stamp_.size() < ref_count) {
    cap_stamp_.resize(ref_count, 0);
    cap_slot_.resize(ref_count, 0);
  }
  for (std::size_t plane = 0; plane < cap_edges_.size(); ++plane) {
    if (cap_edges_[plane].empty()) continue;
    if (++cap_count_ == 0) {  // the stamps wrapped: forget every old one
      std::fill(cap_stamp_.begin(), cap_stamp_.end(), 0);
      cap_count_ = 1;
    }
    const AxisProjection proj(planes_[plane].normal);
    refs.clear();
    points.clear();
    edges.clear();
    const auto cap_point = [&](std::int32_t ref) {
      const auto r = static_cast<std::size_t>(ref);
      if (cap_stamp_[r] != cap_count_) {
        cap_stamp_[r] = cap_count_;
        cap_slot_[r] = static_cast<std::int32_t>(refs.size());
        refs.push_back(ref);
        points.push_back(proj(position(ref)));
      }
      return cap_slot_[r];
    };
    for (const CapEdge& e : cap_edges_[plane]) edges.push_back({cap_point(e[0]), cap_point(e[1])});
    if (fan_convex_cap(points, edges, fan)) {  // the common case: one convex loop (see convex_cap.h)
      for (const Triangle& t : fan) add_cap_triangle(plane, refs, t);
      continue;
    }
    // Points that round to one position would be merged by the triangulation: refuse.
    order.resize(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::int32_t>(k);
    std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
      const Vec2& p = points[static_cast<std::size_t>(a)];
      const Vec2& q = points[static_cast<std::size_t>(b)];
      return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
    });
    for (std::size_t k = 1; k < order.size(); ++k)
      if (points[static_cast<std::size_t>(order[k])] == points[static_cast<std::size_t>(order[k - 1])]) return false;
    const CapTriangulation cap = triangulate_cap(points, edges);
    if (!cap.ok) return false;
    if (!cap_closes_outline(cap.triangles, edges, halfedges)) return false;
    for (const Triangle& t : cap.triangles) add_cap_triangle(plane, refs, t);
  }
  return true;
}

}  // namespace shatter
