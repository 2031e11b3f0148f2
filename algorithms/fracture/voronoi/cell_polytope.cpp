#include "algorithms/fracture/voronoi/cell_polytope.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace shatter {
namespace {

using CornerKey = std::array<int, 3>;  // the three face labels that meet at a corner, sorted

CornerKey corner_key(int a, int b, int c) {
  CornerKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

// The box as six outward counter-clockwise quads. Face labels: -1 x-min, -2 x-max, -3 y-min,
// -4 y-max, -5 z-min, -6 z-max. Corner k has x from bit 0, y from bit 1, z from bit 2.
CellPolytope box_polytope(const Aabb& b) {
  CellPolytope p;
  p.ok = true;
  for (int k = 0; k < 8; ++k)
    p.corners.emplace_back((k & 1) ? b.max.x() : b.min.x(), (k & 2) ? b.max.y() : b.min.y(),
                           (k & 4) ? b.max.z() : b.min.z());
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  // The face across each quad edge is the other box face holding both corners.
  const auto label_of = [](int face) { return -1 - face; };
  for (int f = 0; f < 6; ++f) {
    CellPolytope::Face face;
    face.label = label_of(f);
    for (int k = 0; k < 4; ++k) {
      const int a = quads[f][k];
      const int c = quads[f][(k + 1) % 4];
      face.corners.push_back(a);
      for (int g = 0; g < 6; ++g) {
        if (g == f) continue;
        const int* q = quads[g];
        if (std::find(q, q + 4, a) != q + 4 && std::find(q, q + 4, c) != q + 4) face.across.push_back(label_of(g));
      }
    }
    p.faces.push_back(std::move(face));
  }
  return p;
}

namespace {

/// Clips `p` by plane `label` (negative side kept). False when a corner lies exactly on the plane.
bool clip(CellPolytope& p, const Plane& plane, int label) {
  // Corners made by this clip, by the two faces of the edge they cut: the edge is met from both.
  std::vector<std::pair<CornerKey, std::int32_t>> made;
  std::vector<double> d(p.corners.size());
  bool any_above = false;
  // Only the corners of live faces matter; corners cut off earlier keep a dummy distance.
  std::fill(d.begin(), d.end(), -1.0);
  for (const CellPolytope::Face& face : p.faces)
    for (const std::int32_t c : face.corners) {
      const auto sc = static_cast<std::size_t>(c);
      d[sc] = plane.normal.dot(p.corners[sc] - plane.point);
      if (d[sc] == 0.0) return false;
      any_above |= d[sc] > 0;
    }
  if (!any_above) return true;
  const auto crossing = [&](int fa, int fb, std::int32_t a, std::int32_t b) {
    const CornerKey key = corner_key(fa, fb, label);
    for (const auto& [k, corner] : made)
      if (k == key) return corner;
    const double da = d[static_cast<std::size_t>(a)];
    const double db = d[static_cast<std::size_t>(b)];
    const Vec3& pa = p.corners[static_cast<std::size_t>(a)];
    const Vec3& pb = p.corners[static_cast<std::size_t>(b)];
    const auto corner = static_cast<std::int32_t>(p.corners.size());
    p.corners.push_back(pa + (pb - pa) * (da / (da - db)));
    made.emplace_back(key, corner);
    return corner;
  };
  std::vector<CellPolytope::Face> kept;
  kept.reserve(p.faces.size() + 1);
  // On the new face, a few edges: (start, (end, across)).
  std::vector<std::pair<std::int32_t, std::pair<std::int32_t, int>>> new_edges;
  for (CellPolytope::Face& face : p.faces) {
    const bool untouched = std::all_of(face.corners.begin(), face.corners.end(),
                                       [&](std::int32_t c) { return d[static_cast<std::size_t>(c)] < 0; });
    if (untouched) {  // wholly on the kept side: the face stays as it is
      kept.push_back(std::move(face));
      continue;
    }
    CellPolytope::Face out;
    out.label = face.label;
    const std::size_t n = face.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::int32_t a = face.corners[k];
      const std::int32_t b = face.corners[(k + 1) % n];
      const bool a_in = d[static_cast<std::size_t>(a)] < 0;
      const bool b_in = d[static_cast<std::size_t>(b)] < 0;
      if (a_in) {
        out.corners.push_back(a);
        out.across.push_back(face.across[k]);
      }
      if (a_in != b_in) {
        const std::int32_t x = a_in ? crossing(face.label, face.across[k], a, b)
                                    : crossing(face.label, face.across[k], b, a);
        out.corners.push_back(x);
        out.across.push_back(a_in ? label : face.across[k]);
      }
    }
    for (std::size_t k = 0; k < out.corners.size(); ++k)
      if (out.across[k] == label) new_edges.push_back({out.corners[(k + 1) % out.corners.size()], {out.corners[k], face.label}});
    if (out.corners.size() >= 3) kept.push_back(std::move(out));
  }
  if (new_edges.size() >= 3) {
    // The new face runs along the new edges reversed; they must form one loop.
    CellPolytope::Face face;
    face.label = label;
    // A start met twice would make the loop ambiguous (the map this replaces kept the last one).
    std::sort(new_edges.begin(), new_edges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t k = 1; k < new_edges.size(); ++k)
      if (new_edges[k].first == new_edges[k - 1].first) return false;
    std::int32_t at = new_edges.front().first;
    for (std::size_t step = 0; step < new_edges.size(); ++step) {
      const auto it = std::lower_bound(new_edges.begin(), new_edges.end(), at,
                                       [](const auto& x, std::int32_t key) { return x.first < key; });
      if (it == new_edges.end() || it->first != at) return false;
      face.corners.push_back(at);
      face.across.push_back(it->second.second);
      at = it->second.first;
    }
    if (at != face.corners.front()) return false;
    kept.push_back(std::move(face));
  }
  p.faces = std::move(kept);
  return true;
}

}  // namespace

void clip_polytope(CellPolytope& polytope, const Plane& plane, int label) {
  if (!polytope.ok) return;
  polytope.ok = clip(polytope, plane, label) && !polytope.faces.empty();
}

double max_corner_distance_squared(const CellPolytope& polytope, const Vec3& from) {
  double r2 = 0.0;
  for (const CellPolytope::Face& face : polytope.faces)
    for (const std::int32_t c : face.corners)
      r2 = std::max(r2, (polytope.corners[static_cast<std::size_t>(c)] - from).squaredNorm());
  return r2;
}

CellPolytope cell_polytope(const Aabb& box, std::span<const Plane> planes) {
  CellPolytope p = box_polytope(box);
  for (std::size_t m = 0; m < planes.size(); ++m) clip_polytope(p, planes[m], static_cast<int>(m));
  return p;
}

}  // namespace shatter
