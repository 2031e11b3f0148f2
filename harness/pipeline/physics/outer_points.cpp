#include "harness/pipeline/physics/outer_points.h"

#include <algorithm>
#include <array>
#include <cstddef>

namespace shatter {
namespace {

/// Two unit normals closer than this in dot product are one plane (about 4.5e-5 rad apart).
constexpr double kSamePlaneDot = 1.0 - 1e-9;

/// Relative size of a cross product below which two directions count as on one line (so the point is
/// kept: the flat test only drops a point with neighbours clearly on every side).
constexpr double kLineSine = 1e-12;

/// The vertex's neighbours in pairs, each pair the other two corners of one of its faces in the
/// face's counter-clockwise order (so (a - v) x (b - v) points out of the face).
struct Fan {
  const Vec3& v;
  std::span<const std::int32_t> ring;
  const std::vector<Vec3>& vertices;
  [[nodiscard]] Vec3 edge(std::size_t k) const { return vertices[static_cast<std::size_t>(ring[k])] - v; }
};

/// True when `v` lies within `delta` of the segment from v + a to v + b, strictly between the ends.
bool between(const Vec3& a, const Vec3& b, double delta) {
  if (!(a.dot(b) < 0.0)) return false;  // not on opposite sides of v
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (!(len2 > 0.0)) return false;
  const double t = -a.dot(ab) / len2;  // the foot of v on the line, from the a end
  if (!(t > 0.0 && t < 1.0)) return false;
  return a.cross(b).squaredNorm() <= delta * delta * len2;  // distance |a x b| / |ab|
}

/// True when `v` lies within `delta` of the segment between two of its neighbours: a point on the
/// straight run of an edge.
bool on_segment(const Fan& fan, double delta) {
  const std::size_t k = fan.ring.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3 a = fan.edge(i);
    for (std::size_t j = i + 1; j < k; ++j)
      if (fan.ring[i] != fan.ring[j] && between(a, fan.edge(j), delta)) return true;
  }
  return false;
}

/// on_segment for a vertex on exactly two planes: only the neighbours along the planes' common line
/// (to a loose angle; `between` decides) can be the segment's ends, one on each side. Each face's first
/// other corner is every neighbour once in a closed fan (an open one may miss one: the point is kept).
bool on_crease(const Fan& fan, const Vec3& n1, const Vec3& n2, double delta) {
  const Vec3 line = n1.cross(n2);
  const double len = line.norm();
  if (!(len > 1e-6)) return false;  // the planes face opposite ways: a fold, keep the point
  const Vec3 dir = line / len;
  constexpr int kMost = 4;
  std::array<Vec3, kMost> ahead{};
  std::array<Vec3, kMost> behind{};
  int n_ahead = 0;
  int n_behind = 0;
  for (std::size_t i = 0; i < fan.ring.size(); i += 2) {
    const Vec3 a = fan.edge(i);
    const double along = a.dot(dir);
    if (!((a - along * dir).squaredNorm() <= 1e-12 * a.squaredNorm())) continue;  // off the line
    if (along > 0.0 && n_ahead < kMost) {
      for (int j = 0; j < n_behind; ++j)
        if (between(a, behind[j], delta)) return true;
      ahead[n_ahead++] = a;
    } else if (along < 0.0 && n_behind < kMost) {
      for (int j = 0; j < n_ahead; ++j)
        if (between(ahead[j], a, delta)) return true;
      behind[n_behind++] = a;
    }
  }
  return false;
}

/// True when `v` and its neighbours lie within `delta` of one plane through `v`, the faces around it all
/// face one way, and the neighbours surround it in that plane (no half-plane through v holds them all):
/// a point inside a flat face.
bool inside_flat(const Fan& fan, double delta) {
  const std::size_t k = fan.ring.size();
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i + 1 < k; i += 2) sum += fan.edge(i).cross(fan.edge(i + 1));
  const double len = sum.norm();
  if (!(len > 0.0)) return false;
  const Vec3 n = sum / len;
  for (std::size_t i = 0; i + 1 < k; i += 2)
    if (!(fan.edge(i).cross(fan.edge(i + 1)).dot(n) >= 0.0)) return false;  // a folded face
  for (std::size_t i = 0; i < k; ++i)
    if (!(std::abs(n.dot(fan.edge(i))) <= delta)) return false;
  // The neighbours' directions in the plane; v is inside their hull when, for every direction, some
  // neighbour lies strictly on each side of its line.
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3 a = fan.edge(i);
    if (!(a.norm() > delta)) return false;  // a neighbour at v: keep, rather than reason about it
    bool left = false;
    bool right = false;
    for (std::size_t j = 0; j < k; ++j) {
      const Vec3 b = fan.edge(j);
      const double side = n.dot(a.cross(b));
      const double line = kLineSine * a.norm() * b.norm();
      if (side > line) left = true;
      if (side < -line) right = true;
    }
    if (!(left && right)) return false;
  }
  return true;
}

}  // namespace

VertexPlanes vertex_planes(const Mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  VertexPlanes out;
  // Each vertex's ring holds two neighbours for each face it is on: counted, then offsets.
  out.ring_start.assign(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (const std::int32_t v : t) out.ring_start[static_cast<std::size_t>(v) + 1] += 2;
  for (std::size_t v = 0; v < n; ++v) out.ring_start[v + 1] += out.ring_start[v];
  out.ring.resize(static_cast<std::size_t>(out.ring_start[n]));
  // Scratch kept per thread (the colliders of an event's pieces are planned on workers): a slot for a
  // plane per face a vertex is on (vertex v's from ring_start[v] / 2), how many of them hold a distinct
  // plane, and how much of each ring is filled.
  thread_local std::vector<Vec3> slots;
  thread_local std::vector<std::int32_t> used;
  thread_local std::vector<std::int32_t> filled;
  slots.resize(static_cast<std::size_t>(out.ring_start[n] / 2));
  used.assign(n, 0);
  filled.assign(n, 0);
  const auto add_corner = [&](std::int32_t corner, std::int32_t next, std::int32_t after, bool has_plane,
                              const Vec3& normal) {
    const auto v = static_cast<std::size_t>(corner);
    std::int32_t& at = filled[v];
    const auto ring_at = static_cast<std::size_t>(out.ring_start[v] + at);
    out.ring[ring_at] = next;
    out.ring[ring_at + 1] = after;
    at += 2;
    if (!has_plane) return;
    Vec3* begin = slots.data() + out.ring_start[v] / 2;
    Vec3* end = begin + used[v];
    if (std::none_of(begin, end, [&](const Vec3& m) { return m.dot(normal) > kSamePlaneDot; })) {
      *end = normal;
      ++used[v];
    }
  };
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    Vec3 normal = (mesh.vertices[static_cast<std::size_t>(t[1])] - a).cross(mesh.vertices[static_cast<std::size_t>(t[2])] - a);
    const double len = normal.norm();
    const bool has_plane = len > 0.0;
    if (has_plane) normal /= len;
    add_corner(t[0], t[1], t[2], has_plane, normal);
    add_corner(t[1], t[2], t[0], has_plane, normal);
    add_corner(t[2], t[0], t[1], has_plane, normal);
  }
  // Each vertex's distinct planes, packed in vertex order.
  out.normal_start.resize(n + 1);
  out.normal_start[0] = 0;
  for (std::size_t v = 0; v < n; ++v) out.normal_start[v + 1] = out.normal_start[v] + used[v];
  out.normals.resize(static_cast<std::size_t>(out.normal_start[n]));
  for (std::size_t v = 0; v < n; ++v)
    std::copy_n(slots.begin() + out.ring_start[v] / 2, used[v], out.normals.begin() + out.normal_start[v]);
  return out;
}

std::vector<std::int32_t> outer_point_indices(const Mesh& mesh, const VertexPlanes& planes) {
  std::vector<std::int32_t> kept;
  const std::size_t n = mesh.vertices.size();
  kept.reserve(n);
  if (n == 0) return kept;
  Vec3 lo = mesh.vertices[0];
  Vec3 hi = lo;
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double delta = kOuterPointTolerance * (hi - lo).norm();
  for (std::size_t v = 0; v < n; ++v) {
    const std::span<const Vec3> normals = planes.normals_of(v);
    const Fan fan{mesh.vertices[v], planes.ring_of(v), mesh.vertices};
    bool inner = false;
    if (normals.size() == 2) inner = on_crease(fan, normals[0], normals[1], delta);
    if (normals.size() == 1) inner = on_segment(fan, delta) || inside_flat(fan, delta);
    if (!inner) kept.push_back(static_cast<std::int32_t>(v));
  }
  return kept;
}

}  // namespace shatter
