#include "algorithms/fracture/voronoi/cell_polytope.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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

namespace {

// The box as six outward counter-clockwise quads. Face labels: -1 x-min, -2 x-max, -3 y-min,
// -4 y-max, -5 z-min, -6 z-max. Corner k has x from bit 0, y from bit 1, z from bit 2 (set: the
// box's max).
constexpr int kBoxQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

/// The label of box face `face`.
constexpr int box_label(int face) { return -1 - face; }

/// The label of the face across each edge of each box face: the other box face holding both corners.
/// The same for every box, so found once.
const std::array<std::array<int, 4>, 6>& box_across() {
  static const std::array<std::array<int, 4>, 6> across = [] {
    std::array<std::array<int, 4>, 6> out{};
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 4; ++k) {
        const int a = kBoxQuads[f][k];
        const int c = kBoxQuads[f][(k + 1) % 4];
        for (int g = 0; g < 6; ++g) {
          if (g == f) continue;
          const int* q = kBoxQuads[g];
          if (std::find(q, q + 4, a) != q + 4 && std::find(q, q + 4, c) != q + 4) out[f][k] = box_label(g);
        }
      }
    return out;
  }();
  return across;
}

}  // namespace

CellPolytope box_polytope(const Aabb& b) {
  CellPolytope p;
  p.ok = true;
  p.corners.reserve(8);
  for (int k = 0; k < 8; ++k)
    p.corners.emplace_back((k & 1) ? b.max.x() : b.min.x(), (k & 2) ? b.max.y() : b.min.y(),
                           (k & 4) ? b.max.z() : b.min.z());
  const std::array<std::array<int, 4>, 6>& across = box_across();
  p.faces.resize(6);
  for (int f = 0; f < 6; ++f) {
    CellPolytope::Face& face = p.faces[static_cast<std::size_t>(f)];
    face.label = box_label(f);
    face.corners.assign(kBoxQuads[f], kBoxQuads[f] + 4);
    face.across.assign(across[static_cast<std::size_t>(f)].begin(), across[static_cast<std::size_t>(f)].end());
  }
  return p;
}

namespace {

/// The working storage of clip(), kept per thread: a clip then allocates only when a face outgrows
/// its storage. Faces cut away keep theirs for the next new face.
struct ClipScratch {
  std::vector<std::pair<CornerKey, std::int32_t>> made;  // corners made by this clip, by their three faces
  std::vector<double> d;                                 // signed distance of each corner to the plane
  std::vector<std::pair<std::int32_t, std::pair<std::int32_t, int>>> new_edges;  // (start, (end, across))
  std::vector<std::int32_t> corners;                     // the clipped face being built
  std::vector<int> across;
  std::vector<CellPolytope::Face> spare;                 // faces cut away, their storage kept
};

/// Clips `p` by plane `label` (negative side kept). False when a corner lies exactly on the plane.
/// The surviving faces keep their order and the new face comes last.
bool clip(CellPolytope& p, const Plane& plane, int label) {
  thread_local ClipScratch s;
  s.made.clear();
  s.new_edges.clear();
  bool any_above = false;
  // Only the corners of live faces matter, each measured once (a corner is on three faces or more);
  // corners cut off earlier stay unmeasured (NaN) and are never read.
  s.d.assign(p.corners.size(), std::numeric_limits<double>::quiet_NaN());
  for (const CellPolytope::Face& face : p.faces)
    for (const std::int32_t c : face.corners) {
      const auto sc = static_cast<std::size_t>(c);
      double& d = s.d[sc];
      if (!std::isnan(d)) continue;
      d = plane.normal.dot(p.corners[sc] - plane.point);
      if (d == 0.0) return false;
      any_above |= d > 0;
    }
  if (!any_above) return true;
  const auto crossing = [&](int fa, int fb, std::int32_t a, std::int32_t b) {
    const CornerKey key = corner_key(fa, fb, label);
    for (const auto& [k, corner] : s.made)
      if (k == key) return corner;
    const double da = s.d[static_cast<std::size_t>(a)];
    const double db = s.d[static_cast<std::size_t>(b)];
    const Vec3& pa = p.corners[static_cast<std::size_t>(a)];
    const Vec3& pb = p.corners[static_cast<std::size_t>(b)];
    const auto corner = static_cast<std::int32_t>(p.corners.size());
    p.corners.push_back(pa + (pb - pa) * (da / (da - db)));
    s.made.emplace_back(key, corner);
    return corner;
  };
  // Faces are clipped in place and the survivors packed to the front, in order.
  std::size_t live = 0;
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    CellPolytope::Face& face = p.faces[f];
    const bool untouched = std::all_of(face.corners.begin(), face.corners.end(),
                                       [&](std::int32_t c) { return s.d[static_cast<std::size_t>(c)] < 0; });
    if (!untouched) {
      s.corners.clear();
      s.across.clear();
      const std::size_t n = face.corners.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::int32_t a = face.corners[k];
        const std::int32_t b = face.corners[(k + 1) % n];
        const bool a_in = s.d[static_cast<std::size_t>(a)] < 0;
        const bool b_in = s.d[static_cast<std::size_t>(b)] < 0;
        if (a_in) {
          s.corners.push_back(a);
          s.across.push_back(face.across[k]);
        }
        if (a_in != b_in) {
          const std::int32_t x = a_in ? crossing(face.label, face.across[k], a, b)
                                      : crossing(face.label, face.across[k], b, a);
          s.corners.push_back(x);
          s.across.push_back(a_in ? label : face.across[k]);
        }
      }
      for (std::size_t k = 0; k < s.corners.size(); ++k)
        if (s.across[k] == label) s.new_edges.push_back({s.corners[(k + 1) % s.corners.size()], {s.corners[k], face.label}});
      if (s.corners.size() < 3) continue;  // cut away: left behind the live faces
      face.corners.assign(s.corners.begin(), s.corners.end());
      face.across.assign(s.across.begin(), s.across.end());
    }
    if (live != f) std::swap(p.faces[live], face);
    ++live;
  }
  for (std::size_t f = live; f < p.faces.size(); ++f)
    if (s.spare.size() < 64) s.spare.push_back(std::move(p.faces[f]));
  p.faces.resize(live);
  if (s.new_edges.size() >= 3) {
    // The new face runs along the new edges reversed; they must form one loop.
    CellPolytope::Face face;
    if (!s.spare.empty()) {
      face = std::move(s.spare.back());
      s.spare.pop_back();
      face.corners.clear();
      face.across.clear();
    }
    face.label = label;
    // A start met twice would make the loop ambiguous (the map this replaces kept the last one).
    std::sort(s.new_edges.begin(), s.new_edges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t k = 1; k < s.new_edges.size(); ++k)
      if (s.new_edges[k].first == s.new_edges[k - 1].first) return false;
    std::int32_t at = s.new_edges.front().first;
    for (std::size_t step = 0; step < s.new_edges.size(); ++step) {
      const auto it = std::lower_bound(s.new_edges.begin(), s.new_edges.end(), at,
                                       [](const auto& x, std::int32_t key) { return x.first < key; });
      if (it == s.new_edges.end() || it->first != at) return false;
      face.corners.push_back(at);
      face.across.push_back(it->second.second);
      at = it->second.first;
    }
    if (at != face.corners.front()) return false;
    p.faces.push_back(std::move(face));
  }
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
