#include "algorithms/core/self_intersection.h"

#include "algorithms/core/axis_projection.h"
#include "algorithms/core/height_field_stars.h"
#include "algorithms/core/mesh_fingerprint.h"
#include "algorithms/core/predicates.h"

#include <algorithm>
#include <cassert>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace shatter {
namespace {

using Corners = std::array<Vec3, 3>;

/// An axis along which triangle t does not project to a segment (it is not degenerate), or -1.
int projection_axis(const Corners& t) {
  for (int axis = 2; axis >= 0; --axis)
    if (orient2d(drop_axis(t[0], axis), drop_axis(t[1], axis), drop_axis(t[2], axis)) != 0) return axis;
  return -1;
}

/// Closed segments pq and rs of one plane (2D) have a point in common.
bool segments_meet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const int o1 = orient2d(p, q, r);
  const int o2 = orient2d(p, q, s);
  const int o3 = orient2d(r, s, p);
  const int o4 = orient2d(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  const auto on = [](const Vec2& a, const Vec2& b, const Vec2& x) {  // x collinear with ab: within it?
    return std::min(a.x(), b.x()) <= x.x() && x.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= x.y() &&
           x.y() <= std::max(a.y(), b.y());
  };
  return (o1 == 0 && on(p, q, r)) || (o2 == 0 && on(p, q, s)) || (o3 == 0 && on(r, s, p)) || (o4 == 0 && on(r, s, q));
}

/// Point x lies in the closed triangle abc (2D, any orientation, not degenerate).
bool in_triangle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& x) {
  const int s0 = orient2d(a, b, x);
  const int s1 = orient2d(b, c, x);
  const int s2 = orient2d(c, a, x);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

/// Closed triangles of one plane meet (t not degenerate in the projection along `axis`).
bool coplanar_triangles_meet(const Corners& t, const Corners& u, int axis) {
  std::array<Vec2, 3> a;
  std::array<Vec2, 3> b;
  for (int k = 0; k < 3; ++k) a[k] = drop_axis(t[k], axis), b[k] = drop_axis(u[k], axis);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_meet(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return true;
  if (in_triangle(a[0], a[1], a[2], b[0])) return true;
  return orient2d(b[0], b[1], b[2]) != 0 && in_triangle(b[0], b[1], b[2], a[0]);
}

/// Closed segment pq meets closed triangle abc (3D, not degenerate).
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Corners& t) {
  const int sp = orient3d(t[0], t[1], t[2], p);
  const int sq = orient3d(t[0], t[1], t[2], q);
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {  // the segment lies in the triangle's plane
    const int axis = projection_axis(t);
    const Vec2 a = drop_axis(t[0], axis), b = drop_axis(t[1], axis), c = drop_axis(t[2], axis);
    const Vec2 p2 = drop_axis(p, axis), q2 = drop_axis(q, axis);
    return in_triangle(a, b, c, p2) || segments_meet(a, b, p2, q2) || segments_meet(b, c, p2, q2) ||
           segments_meet(c, a, p2, q2);
  }
  const int s1 = orient3d(p, q, t[0], t[1]);
  const int s2 = orient3d(p, q, t[1], t[2]);
  const int s3 = orient3d(p, q, t[2], t[0]);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

/// The direction from a to x is the direction from a to b (x on the line ab), compared coordinate by
/// coordinate (the sign of a difference of doubles is exact).
bool same_ray(const Vec2& a, const Vec2& b, const Vec2& x) {
  for (int k = 0; k < 2; ++k) {
    const bool bp = b[k] > a[k], bn = b[k] < a[k], xp = x[k] > a[k], xn = x[k] < a[k];
    if (bp != xp || bn != xn) return false;
  }
  return true;
}

/// Two coplanar triangles (a, b, c) and (a, e, f) with only corner a in common meet elsewhere: each
/// lies in its angle at a, so they do exactly when the open angles overlap or share a ray.
bool coplanar_fans_meet(const Vec3& a3, Vec3 b3, Vec3 c3, Vec3 e3, Vec3 f3, int axis) {
  const Vec2 a = drop_axis(a3, axis);
  Vec2 b = drop_axis(b3, axis), c = drop_axis(c3, axis), e = drop_axis(e3, axis), f = drop_axis(f3, axis);
  if (orient2d(a, b, c) < 0) std::swap(b, c);
  const int ef = orient2d(a, e, f);
  if (ef == 0) return false;  // u is degenerate: no area to overlap
  if (ef < 0) std::swap(e, f);
  const auto strictly_in = [&](const Vec2& from, const Vec2& to, const Vec2& x) {
    return orient2d(a, from, x) > 0 && orient2d(a, x, to) > 0;
  };
  const auto on_ray = [&](const Vec2& r, const Vec2& x) { return orient2d(a, r, x) == 0 && same_ray(a, r, x); };
  if (strictly_in(b, c, e) || strictly_in(b, c, f) || strictly_in(e, f, b) || strictly_in(e, f, c)) return true;
  return on_ray(b, e) || on_ray(b, f) || on_ray(c, e) || on_ray(c, f);
}

/// Both non-zero and of one sign.
bool one_side(int x, int y) { return x * y > 0; }

}  // namespace

bool triangles_intersect(const Corners& t, const Corners& u) {
  // Common corners, by position.
  int shared = 0;
  std::array<int, 3> t_of_u{-1, -1, -1};  // corner of t at each corner of u, -1 if none
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (t[i] == u[j]) {
        t_of_u[j] = i;
        ++shared;
        break;
      }
  // Two corners of u at one corner of t: u has no area (a segment or a point) and is left to mesh
  // validation, as a degenerate t is below (the corner bookkeeping that follows needs distinct ones).
  for (int j = 0; j < 3; ++j)
    if (t_of_u[j] >= 0 && t_of_u[j] == t_of_u[(j + 1) % 3]) return false;
  if (shared >= 3) return true;
  // A degenerate triangle has no area to meet anything with: left to mesh validation.
  if (shared == 2) {
    const int t_axis = projection_axis(t);
    if (t_axis < 0) return false;
    // A common edge: they meet elsewhere only folded onto each other, u's free corner on t's side.
    const int j = t_of_u[0] < 0 ? 0 : (t_of_u[1] < 0 ? 1 : 2);
    const int i = 3 - t_of_u[(j + 1) % 3] - t_of_u[(j + 2) % 3];
    if (orient3d(t[0], t[1], t[2], u[j]) != 0) return false;
    const Vec3& p = t[(i + 1) % 3];
    const Vec3& q = t[(i + 2) % 3];
    return one_side(orient2d(drop_axis(p, t_axis), drop_axis(q, t_axis), drop_axis(t[i], t_axis)),
                    orient2d(drop_axis(p, t_axis), drop_axis(q, t_axis), drop_axis(u[j], t_axis)));
  }
  // Sides of u's corners against t's plane; a common corner is on it (and would cost the exact
  // fallback of orient3d, which the filter cannot settle at 0).
  std::array<int, 3> su{0, 0, 0};
  for (int k = 0; k < 3; ++k)
    if (t_of_u[k] < 0) su[k] = orient3d(t[0], t[1], t[2], u[k]);
  if (shared == 1) {
    const int j = t_of_u[0] >= 0 ? 0 : (t_of_u[1] >= 0 ? 1 : 2);
    const int i = t_of_u[j];
    const Vec3& a = t[i];
    const Vec3& b = t[(i + 1) % 3];
    const Vec3& c = t[(i + 2) % 3];
    const Vec3& e = u[(j + 1) % 3];
    const Vec3& f = u[(j + 2) % 3];
    if (one_side(su[(j + 1) % 3], su[(j + 2) % 3])) return false;
    if (projection_axis(u) < 0) return false;
    if (su[(j + 1) % 3] == 0 && su[(j + 2) % 3] == 0) {
      const int t_axis = projection_axis(t);
      return t_axis >= 0 && coplanar_fans_meet(a, b, c, e, f, t_axis);
    }
    if (one_side(orient3d(u[0], u[1], u[2], b), orient3d(u[0], u[1], u[2], c))) return false;
    // Each meets the planes' common line in a stretch from a; they overlap beyond a exactly when the
    // shorter stretch's far end, which lies on the opposite edge, is in the other triangle.
    return projection_axis(t) >= 0 && (segment_meets_triangle(e, f, t) || segment_meets_triangle(b, c, u));
  }
  if ((su[0] > 0 && su[1] > 0 && su[2] > 0) || (su[0] < 0 && su[1] < 0 && su[2] < 0)) return false;
  const int t_axis = projection_axis(t);
  if (t_axis < 0) return false;
  if (su[0] == 0 && su[1] == 0 && su[2] == 0) return coplanar_triangles_meet(t, u, t_axis);
  const std::array<int, 3> st{orient3d(u[0], u[1], u[2], t[0]), orient3d(u[0], u[1], u[2], t[1]),
                              orient3d(u[0], u[1], u[2], t[2])};
  if ((st[0] > 0 && st[1] > 0 && st[2] > 0) || (st[0] < 0 && st[1] < 0 && st[2] < 0)) return false;
  // Not coplanar: the intersection is a segment whose ends lie on edges of t or of u.
  const bool u_flat = projection_axis(u) < 0;
  for (int k = 0; k < 3; ++k) {
    if (segment_meets_triangle(u[k], u[(k + 1) % 3], t)) return true;
    if (!u_flat && segment_meets_triangle(t[k], t[(k + 1) % 3], u)) return true;
  }
  return false;
}

namespace {

/// What the pair loop needs of one triangle, packed together: its box, its lowest grid cell, its
/// corners' indices, and its plane in double (first corner, normal, error scale).
struct TriangleRecord {
  Vec3 origin;                  ///< first corner, m
  Vec3 normal;                  ///< (b - a) x (c - a) as computed, m^2
  double scale = 0.0;           ///< |b - a|_1 |c - a|_1, bounds the round-off of normal . (p - a)
  Aabb box;                     ///< m
  std::array<int, 3> low{};     ///< grid cell of box.min
  Triangle corners{};
};

/// One triangle in one grid cell, packed so that the pair loop over a cell reads memory in order:
/// the box rounded outwards to float (an overlap test that may pass more pairs, never fewer), the
/// corners as keys (the index of a corner whose star is a height field, height_field_stars.h, else
/// the index's complement, which is negative and matches no key), and the axes along which the box
/// starts in this cell (bit k: the box's lowest cell has this cell's coordinate k).
struct CellEntry {
  std::array<float, 3> min;
  std::array<float, 3> max;
  std::array<std::int32_t, 3> keys;
  std::int32_t triangle;
  std::uint32_t home_axes;
};

/// Each pair of triangles is tested once, in the cell of the lower corner of their boxes' overlap:
/// the cell where, along every axis, one of the two boxes starts. So a cell owns a pair exactly when
/// their home axes together are all three, and pairs of the other buckets are not even looked at.
constexpr std::uint32_t kAllAxes = 7;

/// The float next to f (finite) away from zero, or towards it; the smallest subnormal of the given
/// sign after zero. Bit steps: std::nextafter is a library call, and this runs six times per triangle.
float float_step(float f, bool away_from_zero, bool negative_at_zero) {
  if (f == 0.0f) {
    const float tiny = std::numeric_limits<float>::denorm_min();
    return negative_at_zero ? -tiny : tiny;
  }
  const auto bits = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>(away_from_zero ? bits + 1 : bits - 1);
}

float round_down(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? float_step(f, f < 0.0f, true) : f;
}

float round_up(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? float_step(f, f > 0.0f, false) : f;
}

/// Sign of orient3d(a, b, c, p) for the record's triangle (a, b, c): the plane in double decides
/// when it is clear by far more than its round-off (16 u of |b-a|_1 |c-a|_1 |p-a|_1 bounds it, as
/// Shewchuk's permanent does), else the exact predicate. Positive: p below (on the inner side).
int side(const TriangleRecord& t, const Mesh& mesh, const Vec3& p) {
  const Vec3 g = p - t.origin;
  const double d = t.normal.dot(g);
  const double bound = 4e-15 * t.scale * g.cwiseAbs().sum();
  if (bound >= 1e-280) {  // relative bounds fail among subnormal products: the exact predicate decides
    if (d > bound) return -1;  // orient3d is positive on the side opposite to the normal
    if (-d > bound) return 1;
  }
  const Triangle& c = t.corners;
  return orient3d(mesh.vertices[static_cast<std::size_t>(c[0])], mesh.vertices[static_cast<std::size_t>(c[1])],
                  mesh.vertices[static_cast<std::size_t>(c[2])], p);
}

/// False when the pair certainly does not intersect by its corner indices and plane sides alone
/// (most pairs: the neighbours around a vertex or an edge); true when the full test must decide.
bool may_intersect(const TriangleRecord& t, const TriangleRecord& u, const Mesh& mesh) {
  int free_sides[3];
  int free_count = 0;
  for (const std::int32_t v : u.corners) {
    if (v == t.corners[0] || v == t.corners[1] || v == t.corners[2]) continue;
    free_sides[free_count++] = side(t, mesh, mesh.vertices[static_cast<std::size_t>(v)]);
  }
  switch (free_count) {
    case 0: return true;
    case 1: return free_sides[0] == 0;  // a common edge: only a fold onto t's plane can overlap
    case 2: return !one_side(free_sides[0], free_sides[1]);
    default: return !(one_side(free_sides[0], free_sides[1]) && one_side(free_sides[1], free_sides[2]));
  }
}

/// The first intersecting pair, skipping pairs of one part when `part` is given (one label per triangle).
std::optional<std::array<std::int32_t, 2>> find_intersecting_pair(const Mesh& mesh, const std::int32_t* part) {
  const std::size_t n = mesh.triangles.size();
  if (n < 2) return std::nullopt;
  std::vector<TriangleRecord> records(n);
  Aabb all;
  double extent_sum = 0.0;
  for (std::size_t f = 0; f < n; ++f) {
    TriangleRecord& r = records[f];
    r.corners = mesh.triangles[f];
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(r.corners[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(r.corners[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(r.corners[2])];
    const Vec3 e = b - a;
    const Vec3 g = c - a;
    r.origin = a;
    r.normal = e.cross(g);
    r.scale = e.cwiseAbs().sum() * g.cwiseAbs().sum();
    r.box.min = a.cwiseMin(b).cwiseMin(c);
    r.box.max = a.cwiseMax(b).cwiseMax(c);
    all.extend(r.box.min);
    all.extend(r.box.max);
    extent_sum += (r.box.max - r.box.min).maxCoeff();
  }
  // Cells about the mean triangle's extent, at most 4 #F of them.
  const Vec3 size = (all.max - all.min).cwiseMax(1e-300);
  double cell = std::max(extent_sum / static_cast<double>(n), 1e-12 * size.maxCoeff());
  const double budget = 4.0 * static_cast<double>(n);
  const double wanted = std::ceil(size.x() / cell) * std::ceil(size.y() / cell) * std::ceil(size.z() / cell);
  if (wanted > budget) cell *= std::cbrt(wanted / budget) * 1.01;
  std::array<int, 3> dims;
  for (int k = 0; k < 3; ++k) dims[k] = std::clamp(static_cast<int>(std::ceil(size[k] / cell)), 1, 1 << 20);
  const auto coordinate = [&](double x, int k) {
    return std::clamp(static_cast<int>((x - all.min[k]) / cell), 0, dims[k] - 1);
  };
  const auto index = [&](int x, int y, int z) { return (static_cast<std::size_t>(z) * dims[1] + y) * dims[0] + x; };
  const std::size_t cells = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  std::vector<std::array<int, 3>> high(n);
  std::vector<std::int32_t> start(cells + 1, 0);
  for (std::size_t f = 0; f < n; ++f) {
    TriangleRecord& r = records[f];
    for (int k = 0; k < 3; ++k) r.low[k] = coordinate(r.box.min[k], k), high[f][k] = coordinate(r.box.max[k], k);
    for (int z = r.low[2]; z <= high[f][2]; ++z)
      for (int y = r.low[1]; y <= high[f][1]; ++y)
        for (int x = r.low[0]; x <= high[f][0]; ++x) ++start[index(x, y, z) + 1];
  }
  for (std::size_t c = 1; c <= cells; ++c) start[c] += start[c - 1];
  const std::vector<std::uint8_t> height_field = height_field_stars(mesh);
  std::vector<CellEntry> members(static_cast<std::size_t>(start[cells]));
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < n; ++f) {
    const TriangleRecord& r = records[f];
    CellEntry entry{};
    for (int k = 0; k < 3; ++k) entry.min[k] = round_down(r.box.min[k]), entry.max[k] = round_up(r.box.max[k]);
    entry.triangle = static_cast<std::int32_t>(f);
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = r.corners[k];
      entry.keys[k] = height_field[static_cast<std::size_t>(v)] ? v : ~v;
    }
    for (int z = r.low[2]; z <= high[f][2]; ++z)
      for (int y = r.low[1]; y <= high[f][1]; ++y)
        for (int x = r.low[0]; x <= high[f][0]; ++x) {
          entry.home_axes = static_cast<std::uint32_t>(x == r.low[0]) | static_cast<std::uint32_t>(y == r.low[1]) << 1 |
                            static_cast<std::uint32_t>(z == r.low[2]) << 2;
          members[static_cast<std::size_t>(fill[index(x, y, z)]++)] = entry;
        }
  }
  const auto corners = [&](const TriangleRecord& r) {
    return Corners{mesh.vertices[static_cast<std::size_t>(r.corners[0])], mesh.vertices[static_cast<std::size_t>(r.corners[1])],
                   mesh.vertices[static_cast<std::size_t>(r.corners[2])]};
  };
  std::vector<std::array<std::int32_t, 2>> candidates;
  std::vector<CellEntry> sorted;  // one cell's members, by home axes
  // The pairs of triangles of buckets `a` and `b` (all pairs within `a` when they are the same) whose
  // boxes overlap and that share no height-field corner, gathered without a branch per pair (which
  // way the tests go is close to a coin toss, and mispredictions were most of the loop's time).
  const auto gather = [&candidates](const CellEntry* a_first, const CellEntry* a_last, const CellEntry* b_first,
                                    const CellEntry* b_last, bool same) {
    for (const CellEntry* ea = a_first; ea != a_last; ++ea) {
      for (const CellEntry* eb = same ? ea + 1 : b_first; eb != b_last; ++eb) {
        const bool overlap = (ea->min[0] <= eb->max[0]) & (eb->min[0] <= ea->max[0]) & (ea->min[1] <= eb->max[1]) &
                             (eb->min[1] <= ea->max[1]) & (ea->min[2] <= eb->max[2]) & (eb->min[2] <= ea->max[2]);
        bool in_flat_star = false;  // such a pair meets only where it shares corners
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) in_flat_star |= (ea->keys[i] == eb->keys[j]) & (ea->keys[i] >= 0);
        candidates.push_back({ea->triangle, eb->triangle});
        candidates.resize(candidates.size() - static_cast<std::size_t>(!(overlap & !in_flat_star)));
      }
    }
  };
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const std::size_t c = index(x, y, z);
        const CellEntry* first = members.data() + start[c];
        const CellEntry* last = members.data() + start[c + 1];
        if (last - first < 2) continue;
        std::array<std::int32_t, kAllAxes + 2> bucket{};
        for (const CellEntry* e = first; e != last; ++e) ++bucket[e->home_axes + 1];
        for (std::uint32_t h = 1; h <= kAllAxes + 1; ++h) bucket[h] += bucket[h - 1];
        sorted.resize(static_cast<std::size_t>(last - first));
        std::array<std::int32_t, kAllAxes + 1> next{};
        std::copy(bucket.begin(), bucket.end() - 1, next.begin());
        for (const CellEntry* e = first; e != last; ++e) sorted[static_cast<std::size_t>(next[e->home_axes]++)] = *e;
        const auto begin_of = [&](std::uint32_t h) { return sorted.data() + bucket[h]; };
        candidates.clear();
        for (std::uint32_t h = 0; h <= kAllAxes; ++h)
          for (std::uint32_t g = h; g <= kAllAxes; ++g)
            if ((h | g) == kAllAxes) gather(begin_of(h), begin_of(h + 1), begin_of(g), begin_of(g + 1), h == g);
        for (auto [a, b] : candidates) {
          if (a > b) std::swap(a, b);  // the order every-pair testing uses (a degenerate pair may depend on it)
          if (part != nullptr && part[a] == part[b]) continue;
          const TriangleRecord& ra = records[static_cast<std::size_t>(a)];
          const TriangleRecord& rb = records[static_cast<std::size_t>(b)];
          if (may_intersect(ra, rb, mesh) && may_intersect(rb, ra, mesh) && triangles_intersect(corners(ra), corners(rb)))
            return std::array<std::int32_t, 2>{a, b};
        }
      }
  return std::nullopt;
}

}  // namespace

std::optional<std::array<std::int32_t, 2>> find_self_intersection(const Mesh& mesh) {
  return find_intersecting_pair(mesh, nullptr);
}

std::optional<std::array<std::int32_t, 2>> find_intersection_between_parts(const Mesh& mesh,
                                                                           std::span<const std::int32_t> part) {
  assert(part.size() == mesh.triangles.size());
  return find_intersecting_pair(mesh, part.data());
}

Status check_no_self_intersection(const Mesh& mesh, std::string_view who, SelfIntersectionVerdicts* verdicts) {
  const std::uint64_t fingerprint = verdicts != nullptr ? mesh_fingerprint(mesh) : 0;
  if (verdicts != nullptr && verdicts->remembers(fingerprint)) return {};
  const auto pair = find_self_intersection(mesh);
  if (!pair) {
    if (verdicts != nullptr) verdicts->remember(fingerprint);
    return {};
  }
  return Error{std::string(who) + ": the input mesh intersects itself (triangles " + std::to_string((*pair)[0]) +
               " and " + std::to_string((*pair)[1]) + ")"};
}

}  // namespace shatter
