/// Constrained Delaunay triangulation of cap polygons (Sloan 1993) with exact predicates: the insertion
/// order, the deduplication of points, the super triangle and the selection of the inside. The data
/// structure and its steps are in constrained_delaunay.h.
///
/// Points are deduplicated, a super triangle far outside the points closes the triangulation (every
/// predicate runs on the exact input doubles, so its size only needs to be generous), and the inside is
/// the set of triangles with positive winding number, found by a flood fill from the super triangle.
/// All buffers live in a thread-local triangulation reused across calls: scratch only, no result is
/// carried from one call to the next.

#include "algorithms/core/cap_triangulator.h"

#include "algorithms/core/constrained_delaunay.h"
#include "algorithms/core/predicates.h"
#include "algorithms/core/random.h"

#include <algorithm>
#include <cassert>
#include <climits>
#include <cmath>
#include <utility>

namespace shatter {
namespace {

using cdt::at;
using cdt::Constraint;
using cdt::Id;
using cdt::Tri;
using cdt::Triangulation;

/// Sloan's bin order: rows of bins, alternate rows right to left, so consecutive points are close.
void sort_by_bins(Triangulation& ws, Id n, const Vec2& lo, double size) {
  const Id side = std::max<Id>(1, static_cast<Id>(std::sqrt(n) / 2));
  ws.keys.clear();
  for (Id i = 0; i < n; ++i) {
    // In [0, 1]^2 up to rounding; ordering only. Divided, not multiplied by 1 / size: a cap a few
    // subnormals wide has 1 / size = inf. The bin is clamped in double before the conversion, so no
    // rounding (or a non-finite value) can reach an out-of-range integer conversion.
    const Vec2 q = (ws.p(i) - lo) / size;
    const auto bin = [&](double x) {
      const double b = x * static_cast<double>(side);
      return b >= 0.0 ? static_cast<Id>(std::min(b, static_cast<double>(side - 1))) : Id{0};
    };
    const Id row = bin(q.y());
    const Id col = row % 2 == 0 ? bin(q.x()) : side - 1 - bin(q.x());
    ws.keys.emplace_back(static_cast<std::int64_t>(row) * side + col, i);
  }
  std::sort(ws.keys.begin(), ws.keys.end());
}

/// Biased randomized insertion order (Amenta, Choi, Rote 2003): the bin order shuffled, then cut into
/// rounds of doubling size, each round in bin order. Random order bounds the expected flips by O(n)
/// whatever the points are (nearly cocircular points in bin order make O(n) flips per insertion: a
/// star polygon of 100,000 corners took 6 s); the rounds keep the walks short.
void randomize_rounds(Triangulation& ws) {
  const std::size_t n = ws.keys.size();
  SplitMix64 rng(0x5DEECE66DULL + n);  // fixed seed: the same points give the same triangulation
  for (std::size_t i = n; i > 1; --i) std::swap(ws.keys[i - 1], ws.keys[rng.next() % i]);
  for (std::size_t begin = 0, end = std::min<std::size_t>(n, 64); begin < n;
       begin = end, end = std::min(n, 2 * end))
    std::sort(ws.keys.begin() + static_cast<std::ptrdiff_t>(begin), ws.keys.begin() + static_cast<std::ptrdiff_t>(end));
}

CapTriangulation failure(std::string error) {
  CapTriangulation out;
  out.ok = false;
  out.error = std::move(error);
  return out;
}

}  // namespace

CapTriangulation triangulate_cap(std::span<const Vec2> points, std::span<const CapEdge> edges, InsertionOrder order) {
  thread_local Triangulation ws;
  CapTriangulation out;

  // Used points, deduplicated by exact coordinates; the smallest input index represents a group.
  ws.local.assign(points.size(), -1);
  ws.order.clear();
  for (const CapEdge& edge : edges) {
    for (const Id i : edge) {
      assert(i >= 0 && at(i) < points.size());
      if (ws.local[at(i)] == -1) {
        if (!points[at(i)].allFinite()) return failure("cap: non-finite point coordinate");
        ws.local[at(i)] = 0;
        ws.order.push_back(i);
      }
    }
  }
  std::sort(ws.order.begin(), ws.order.end(), [&](Id i, Id j) {
    const Vec2 &a = points[at(i)], &b = points[at(j)];
    return a.x() != b.x() ? a.x() < b.x() : (a.y() != b.y() ? a.y() < b.y() : i < j);
  });
  ws.pts.clear();
  ws.original.clear();
  for (std::size_t k = 0; k < ws.order.size(); ++k) {
    const Id i = ws.order[k];
    if (k == 0 || points[at(i)] != points[at(ws.order[k - 1])]) {
      ws.pts.push_back(points[at(i)]);
      ws.original.push_back(i);
    }
    ws.local[at(i)] = static_cast<Id>(ws.pts.size() - 1);
  }
  const auto n = static_cast<Id>(ws.pts.size());
  if (n < 3) return out;
  // Exact predicates are exact only while their products neither underflow nor overflow: a cap whose
  // coordinates are all subnormal (a cut through a corner a few 1e-311 wide) has every orientation
  // read as 0. Scaling by a power of two is exact and keeps every predicate's sign (they are
  // homogeneous), so far-out magnitudes are brought to about 1 first.
  double largest = 0.0;
  for (const Vec2& q : ws.pts) largest = std::max(largest, q.cwiseAbs().maxCoeff());
  if (largest > 0.0 && (largest < 0x1p-400 || largest > 0x1p400)) {
    const int exponent = -std::ilogb(largest);  // 2^exponent itself may not be a double (2^1030)
    for (Vec2& q : ws.pts) q = Vec2(std::ldexp(q.x(), exponent), std::ldexp(q.y(), exponent));
  }

  // Super triangle well outside the bounding box.
  Vec2 lo = ws.pts[0], hi = ws.pts[0];
  for (const Vec2& q : ws.pts) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const double size = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  const Vec2 center = 0.5 * (lo + hi);
  ws.pts.emplace_back(center.x() - 30.0 * size, center.y() - 30.0 * size);
  ws.pts.emplace_back(center.x() + 30.0 * size, center.y() - 30.0 * size);
  ws.pts.emplace_back(center.x(), center.y() + 30.0 * size);
  ws.tris.clear();
  ws.tris.reserve(2 * at(n) + 8);
  ws.vert_tri.assign(at(n) + 3, -1);
  const Id root = ws.new_tri();
  ws.set(root, n, n + 1, n + 2);
  for (int i = 0; i < 3; ++i) ws.link(root, i, -1, 0);

  sort_by_bins(ws, n, lo, size);
  if (order == InsertionOrder::randomized_rounds) randomize_rounds(ws);
  Id hint = root;
  for (const auto& key : ws.keys) ws.insert(key.second, hint);

  // Constraints: canonical direction, opposite copies cancel.
  ws.constraints.clear();
  for (const CapEdge& edge : edges) {
    const Id a = ws.local[at(edge[0])];
    const Id b = ws.local[at(edge[1])];
    if (a == b) continue;
    ws.constraints.push_back(a < b ? Constraint{a, b, 1} : Constraint{b, a, -1});
  }
  std::sort(ws.constraints.begin(), ws.constraints.end(),
            [](const Constraint& x, const Constraint& y) { return x.u != y.u ? x.u < y.u : x.v < y.v; });
  ws.fresh.clear();
  for (std::size_t k = 0; k < ws.constraints.size();) {
    Constraint c = ws.constraints[k++];
    while (k < ws.constraints.size() && ws.constraints[k].u == c.u && ws.constraints[k].v == c.v)
      c.weight += ws.constraints[k++].weight;
    if (c.weight != 0 && !ws.recover(c.u, c.v, c.weight, out.error)) return failure(out.error);
  }
  if (!ws.restore_delaunay(out.error)) return failure(out.error);

  // Winding numbers by flood fill from the super triangle (winding 0).
  ws.winding.assign(ws.tris.size(), INT_MIN);
  const Id start = ws.vert_tri[at(n)];
  ws.winding[at(start)] = 0;
  ws.stack.assign(1, start);
  while (!ws.stack.empty()) {
    const Id t = ws.stack.back();
    ws.stack.pop_back();
    const Tri& tri = ws.tri_at(t);
    for (int i = 0; i < 3; ++i) {
      const Id nb = tri.n[i];
      if (nb < 0) continue;
      const Id expected = ws.winding[at(t)] - tri.w[i];
      Id& wn = ws.winding[at(nb)];
      if (wn == INT_MIN) {
        wn = expected;
        ws.stack.push_back(nb);
      } else if (wn != expected) {
        return failure("cap: edges do not form closed loops");
      }
    }
  }
  for (std::size_t t = 0; t < ws.tris.size(); ++t) {
    if (ws.winding[t] <= 0) continue;
    const Tri& tri = ws.tris[t];
    assert(tri.v[0] < n && tri.v[1] < n && tri.v[2] < n);
    out.triangles.push_back({ws.original[at(tri.v[0])], ws.original[at(tri.v[1])], ws.original[at(tri.v[2])]});
  }
  return out;
}

}  // namespace shatter
