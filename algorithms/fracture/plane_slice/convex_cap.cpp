#include "algorithms/fracture/plane_slice/convex_cap.h"

#include "algorithms/core/predicates.h"

#include <cmath>
#include <cstdint>

namespace shatter {
namespace {

/// Sine of the turn at a corner below which the corner counts as straight: far above the relative
/// round-off of a rounded construction (1e-16), far below any turn of a tessellated surface.
constexpr double kStraightTurn = 1e-9;

/// a before b in (x, y) order.
bool lexicographic_less(const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); }

}  // namespace

bool fan_convex_cap(std::span<const Vec2> points, std::span<const CapEdge> edges, std::vector<Triangle>& triangles) {
  const std::size_t n = edges.size();
  if (n < 3) return false;
  // One successor per point; the walk from the first edge must use every edge once and come back.
  thread_local std::vector<std::int32_t> next, loop;
  next.assign(points.size(), -1);
  for (const CapEdge& e : edges) {
    std::int32_t& slot = next[static_cast<std::size_t>(e[0])];
    if (slot >= 0) return false;
    slot = e[1];
  }
  loop.clear();
  for (std::int32_t v = edges.front()[0]; loop.size() <= n;) {
    loop.push_back(v);
    v = next[static_cast<std::size_t>(v)];
    if (v < 0) return false;
    if (v == edges.front()[0]) break;
  }
  if (loop.size() != n) return false;  // several loops, or a walk that does not close

  double largest = 0.0;
  for (const std::int32_t v : loop) {
    const Vec2& p = points[static_cast<std::size_t>(v)];
    if (!p.allFinite()) return false;
    largest = std::max(largest, p.cwiseAbs().maxCoeff());
  }
  if (!(largest >= 0x1p-400 && largest <= 0x1p400)) return false;

  std::size_t minima = 0, first = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = points[static_cast<std::size_t>(loop[(k + n - 1) % n])];
    const Vec2& b = points[static_cast<std::size_t>(loop[k])];
    const Vec2& c = points[static_cast<std::size_t>(loop[(k + 1) % n])];
    if (orient2d(a, b, c) <= 0) return false;
    // A corner that turns by no more than round-off is a point of one straight side (three points
    // on one line of a flat face, for example, rounded apart): a fan from a point of that side would
    // make a sliver lying in the face, folded onto the face's own triangles. Declined: the
    // constrained Delaunay triangulation never makes that sliver.
    const Vec2 u = b - a, w = c - b;
    if (u.x() * w.y() - u.y() * w.x() <= kStraightTurn * u.norm() * w.norm()) return false;
    if (lexicographic_less(b, a) && lexicographic_less(b, c)) {
      ++minima;
      first = k;
    }
  }
  if (minima != 1) return false;

  triangles.clear();
  const std::int32_t apex = loop[first];
  for (std::size_t k = 1; k + 1 < n; ++k)
    triangles.push_back({apex, loop[(first + k) % n], loop[(first + k + 1) % n]});
  return true;
}

}  // namespace shatter
