/// Constrained Delaunay triangulation of cap polygons (Sloan 1993) with exact predicates.
///
/// Design note. Triangles live in one array; triangle t has vertices v[0..2] counter-clockwise,
/// n[i] = the triangle across the edge opposite v[i] (edge v[i+1] -> v[i+2]), -1 on the super
/// triangle's boundary, and w[i] = the net number of constraints running v[i+1] -> v[i+2] (the
/// neighbour holds -w). An edge with w != 0 is a constraint and is never flipped. Points are
/// deduplicated, a super triangle far outside the points closes the triangulation (every predicate
/// runs on the exact input doubles, so its size only needs to be generous), and the inside is the set
/// of triangles with positive winding number, found by a flood fill from the super triangle.
/// All buffers live in a thread-local workspace reused across calls.

#include "algorithms/core/cap_triangulator.h"

#include "algorithms/core/predicates.h"
#include "algorithms/core/random.h"

#include <algorithm>
#include <cassert>
#include <climits>
#include <cmath>
#include <utility>

namespace shatter {
namespace {

using Id = std::int32_t;
inline std::size_t at(Id i) { return static_cast<std::size_t>(i); }
constexpr int kNext[3] = {1, 2, 0};
constexpr int kPrev[3] = {2, 0, 1};

struct Tri {
  Id v[3], n[3], w[3];
};

/// An undirected constraint u < v with the net count of u -> v minus v -> u edges.
struct Constraint {
  Id u, v, weight;
};

bool fail(std::string& error, const char* message) {
  error = message;
  return false;
}

struct Workspace {
  std::vector<Vec2> pts;                     // local points, then the 3 super vertices
  std::vector<Id> original;        // local point -> first input index
  std::vector<Id> local;           // input index -> local point, -1 when unused
  std::vector<Id> order;           // scratch
  std::vector<std::pair<std::int64_t, Id>> keys;
  std::vector<Tri> tris;
  std::vector<Id> vert_tri;        // a triangle incident to each local point
  std::vector<Id> stack;
  std::vector<Constraint> constraints;
  std::vector<std::pair<Id, Id>> crossing;  // Sloan's queue (ring buffer use)
  std::vector<std::pair<Id, Id>> fresh;     // edges made by recovery flips
  std::vector<Id> winding;
  std::uint32_t walk_seed = 0;

  Tri& tri_at(Id t) { return tris[at(t)]; }
  [[nodiscard]] const Tri& tri_at(Id t) const { return tris[at(t)]; }
  [[nodiscard]] const Vec2& p(Id i) const { return pts[at(i)]; }
  [[nodiscard]] int orient(Id a, Id b, Id c) const {
    return orient2d(p(a), p(b), p(c));
  }

  void set(Id t, Id a, Id b, Id c) {
    Tri& tri = tri_at(t);
    tri.v[0] = a, tri.v[1] = b, tri.v[2] = c;
    vert_tri[at(a)] = vert_tri[at(b)] = vert_tri[at(c)] = t;
  }
  /// Makes t's edge i face triangle u (whose edge faces back is found by the caller) with weight wt.
  void link(Id t, int i, Id u, Id wt) {
    Tri& tri = tri_at(t);
    tri.n[i] = u;
    tri.w[i] = wt;
    if (u < 0) return;
    Tri& other = tri_at(u);
    const Id a = tri.v[kNext[i]];
    for (int j = 0; j < 3; ++j) {
      if (other.v[kPrev[j]] == a) {  // other's edge j runs b -> a
        other.n[j] = t;
        other.w[j] = -wt;
        return;
      }
    }
    assert(false && "link: triangles do not share the edge");
  }
  Id new_tri() {
    tris.emplace_back();
    return static_cast<Id>(tris.size() - 1);
  }
  /// Index in t of the vertex opposite the edge shared with neighbour u.
  [[nodiscard]] int opposite_index(Id u, Id t) const {
    const Tri& tri = tri_at(u);
    for (int j = 0; j < 3; ++j)
      if (tri.n[j] == t) return j;
    assert(false && "opposite_index: not neighbours");
    return 0;
  }

  void flip(Id t, int i);
  Id locate(Id start, Id q, int& edge);
  void insert(Id q, Id& hint);
  bool find_edge(Id a, Id b, Id& t, int& i) const;
  /// find_edge for an edge known to exist.
  void edge_of(Id a, Id b, Id& t, int& i) const {
    [[maybe_unused]] const bool found = find_edge(a, b, t, i);
    assert(found);
  }
  bool recover(Id u, Id v, Id weight, std::string& error);
  bool restore_delaunay(std::string& error);
};

/// Flips the edge opposite v[i] of t. t = (p, a, b), across it u = (q, b, a); afterwards
/// t = (p, a, q) and u = (q, b, p), both still holding p.
void Workspace::flip(Id t, int i) {
  const Id u = tri_at(t).n[i];
  const int j = opposite_index(u, t);
  const Tri ot = tri_at(t);
  const Tri ou = tri_at(u);
  assert(ot.w[i] == 0);
  const Id p = ot.v[i], a = ot.v[kNext[i]], b = ot.v[kPrev[i]], q = ou.v[j];
  set(t, p, a, q);
  set(u, q, b, p);
  link(t, 0, ou.n[kNext[j]], ou.w[kNext[j]]);  // across a -> q
  link(t, 2, ot.n[kPrev[i]], ot.w[kPrev[i]]);  // across p -> a
  link(u, 0, ot.n[kNext[i]], ot.w[kNext[i]]);  // across b -> p
  link(u, 2, ou.n[kPrev[j]], ou.w[kPrev[j]]);  // across q -> b
  link(t, 1, u, 0);                            // the new diagonal q -> p
}

/// Visibility walk from `start` to the triangle containing point q; `edge` = index of the edge q lies
/// on, or -1 when q is strictly inside. The start edge is varied so the walk cannot cycle.
Id Workspace::locate(Id start, Id q, int& edge) {
  Id t = start;
  const std::size_t limit = 4 * tris.size() + 64;
  for (std::size_t step = 0; step < limit; ++step) {
    const Tri& tri = tri_at(t);
    walk_seed = walk_seed * 1664525u + 1013904223u;
    const int first = static_cast<int>((walk_seed >> 16) % 3);
    int zero = -1, zeros = 0;
    bool moved = false;
    for (int k = 0; k < 3 && !moved; ++k) {
      const int i = (first + k) % 3;
      const int o = orient(tri.v[kNext[i]], tri.v[kPrev[i]], q);
      if (o < 0) t = tri.n[i], moved = true;
      if (o == 0) zero = i, ++zeros;
    }
    assert(t >= 0 && "point outside the super triangle");
    if (moved) continue;
    assert(zeros < 2 && "duplicate point");
    edge = zeros == 1 ? zero : -1;
    return t;
  }
  // Not reached for a Delaunay triangulation; a scan keeps the call total anyway.
  for (Id s = 0; at(s) < tris.size(); ++s) {
    const Tri& tri = tri_at(s);
    int o[3];
    for (int i = 0; i < 3; ++i) o[i] = orient(tri.v[kNext[i]], tri.v[kPrev[i]], q);
    if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
    edge = o[0] == 0 ? 0 : (o[1] == 0 ? 1 : (o[2] == 0 ? 2 : -1));
    return s;
  }
  assert(false && "locate: point in no triangle");
  edge = -1;
  return 0;
}

/// Inserts point q (Bowyer-Watson by splitting and Lawson flips).
void Workspace::insert(Id q, Id& hint) {
  int edge = -1;
  const Id t = locate(hint, q, edge);
  stack.clear();
  if (edge < 0) {
    const Tri o = tri_at(t);
    const Id t1 = new_tri(), t2 = new_tri();
    set(t, q, o.v[0], o.v[1]);
    set(t1, q, o.v[1], o.v[2]);
    set(t2, q, o.v[2], o.v[0]);
    link(t, 0, o.n[2], o.w[2]);
    link(t1, 0, o.n[0], o.w[0]);
    link(t2, 0, o.n[1], o.w[1]);
    link(t, 1, t1, 0);  // v1 -> q
    link(t1, 1, t2, 0);
    link(t2, 1, t, 0);
    stack.insert(stack.end(), {t, t1, t2});
  } else {
    // q on the edge a -> b of t = (p, a, b); u = (r, b, a) across it.
    const Tri ot = tri_at(t);
    const Id u = ot.n[edge];
    assert(u >= 0);
    const int j = opposite_index(u, t);
    const Tri ou = tri_at(u);
    const Id p = ot.v[edge], a = ot.v[kNext[edge]], b = ot.v[kPrev[edge]], r = ou.v[j];
    const Id t1 = new_tri(), u1 = new_tri();
    set(t, q, p, a);
    set(t1, q, b, p);
    set(u, q, r, b);
    set(u1, q, a, r);
    link(t, 0, ot.n[kPrev[edge]], ot.w[kPrev[edge]]);
    link(t1, 0, ot.n[kNext[edge]], ot.w[kNext[edge]]);
    link(u, 0, ou.n[kPrev[j]], ou.w[kPrev[j]]);
    link(u1, 0, ou.n[kNext[j]], ou.w[kNext[j]]);
    link(t, 1, u1, ot.w[edge]);  // a -> q, half of the split edge
    link(t, 2, t1, 0);           // q -> p
    link(t1, 2, u, ot.w[edge]);  // q -> b, the other half
    link(u, 2, u1, 0);           // q -> r
    stack.insert(stack.end(), {t, t1, u, u1});
  }
  hint = t;
  // Lawson: every triangle on the stack has q at v[0]; check the edge opposite q.
  while (!stack.empty()) {
    const Id s = stack.back();
    stack.pop_back();
    const Tri& tri = tri_at(s);
    const Id nb = tri.n[0];
    if (nb < 0 || tri.w[0] != 0) continue;
    const Tri& other = tri_at(nb);
    const Id r = other.v[opposite_index(nb, s)];
    if (incircle(p(tri.v[0]), p(tri.v[1]), p(tri.v[2]), p(r)) > 0) {
      flip(s, 0);  // s = (q, a, r), nb = (r, b, q)
      Tri& nt = tri_at(nb);
      nt = Tri{{nt.v[2], nt.v[0], nt.v[1]}, {nt.n[2], nt.n[0], nt.n[1]}, {nt.w[2], nt.w[0], nt.w[1]}};  // q first
      stack.push_back(s);
      stack.push_back(nb);
    }
  }
}

/// Finds the triangle t whose edge i runs a -> b, by turning around a.
bool Workspace::find_edge(Id a, Id b, Id& t, int& i) const {
  const Id start = vert_tri[at(a)];
  for (int direction = 0; direction < 2; ++direction) {
    Id s = start;
    for (std::size_t step = 0; step <= tris.size() && s >= 0; ++step) {
      const Tri& tri = tri_at(s);
      const int k = tri.v[0] == a ? 0 : (tri.v[1] == a ? 1 : 2);
      assert(tri.v[k] == a);
      if (tri.v[kNext[k]] == b) {
        t = s;
        i = kPrev[k];
        return true;
      }
      // Counter-clockwise around a first; clockwise from the start when the star is open.
      s = direction == 0 ? tri.n[kNext[k]] : tri.n[kPrev[k]];
      if (s == start) break;
    }
    if (s == start) break;
  }
  return false;
}

/// Makes the segment u -> v (or its pieces, split at points lying on it) edges of the triangulation
/// by Sloan's flips, and adds `weight` to them.
bool Workspace::recover(Id u, Id v, Id weight, std::string& error) {
  Id from = u;
  while (from != v) {
    // Triangle (from, a, b) around `from` whose wedge holds the ray from -> v.
    Id t = vert_tri[at(from)];
    Id end = -1;
    Id a = -1, b = -1;
    int e = -1;
    for (std::size_t step = 0; step <= tris.size(); ++step) {
      const Tri& tri = tri_at(t);
      const int k = tri.v[0] == from ? 0 : (tri.v[1] == from ? 1 : 2);
      a = tri.v[kNext[k]];
      b = tri.v[kPrev[k]];
      const int oa = a == v ? 0 : orient(from, v, a);
      if (oa == 0) {
        const Vec2 da = p(a) - p(from), dv = p(v) - p(from);  // sign tests only: exact
        const bool on_ray = (da.x() > 0) == (dv.x() > 0) && (da.x() < 0) == (dv.x() < 0) &&
                            (da.y() > 0) == (dv.y() > 0) && (da.y() < 0) == (dv.y() < 0);
        if (on_ray) {
          end = a;  // the edge from -> a already exists
          break;
        }
      } else if (oa < 0 && orient(from, v, b) > 0) {
        e = k;
        break;
      }
      t = tri.n[kNext[k]];
    }
    if (end < 0 && e < 0) return fail(error, "cap: constraint recovery found no triangle around a vertex");
    if (end < 0) {
      // Walk along from -> v collecting the crossed edges (a right of the segment, b left).
      crossing.clear();
      for (std::size_t step = 0;; ++step) {
        const Tri& tri = tri_at(t);
        if (tri.w[e] != 0 || step > tris.size()) return fail(error, "cap: constraint edges cross each other");
        crossing.emplace_back(a, b);
        const Id nt = tri.n[e];
        const int jj = opposite_index(nt, t);
        const Id w = tri_at(nt).v[jj];
        const int ow = w == v ? 0 : orient(from, v, w);
        if (ow == 0) {
          end = w;  // v itself, or a point lying on the segment: split there
          break;
        }
        t = nt;
        (ow > 0 ? b : a) = w;
        e = ow > 0 ? kNext[jj] : kPrev[jj];
      }
      // Sloan: flip crossing edges whose quadrilateral is strictly convex; requeue the others.
      const std::size_t n0 = crossing.size();
      const std::size_t limit = 16 * (n0 + 4) * (n0 + 4);
      std::size_t head = 0;
      for (std::size_t iteration = 0; head < crossing.size(); ++iteration) {
        if (iteration > limit) return fail(error, "cap: constraint recovery did not converge");
        const auto [ea, eb] = crossing[head++];
        Id s = -1;
        int i = -1;
        edge_of(ea, eb, s, i);
        const Id c = tri_at(s).v[i];
        const Id ns = tri_at(s).n[i];
        const Id d = tri_at(ns).v[opposite_index(ns, s)];
        if (orient(c, d, ea) * orient(c, d, eb) < 0) {
          flip(s, i);
          (orient(from, end, c) * orient(from, end, d) < 0 ? crossing : fresh).emplace_back(c, d);
        } else {
          crossing.emplace_back(ea, eb);
        }
      }
    }
    Id s = -1;
    int i = -1;
    edge_of(from, end, s, i);
    Tri& tri = tri_at(s);
    tri.w[i] += weight;
    link(s, i, tri.n[i], tri.w[i]);
    from = end;
  }
  return true;
}

/// Lawson flips on the edges made by constraint recovery, constraints excepted (Sloan's last step).
bool Workspace::restore_delaunay(std::string& error) {
  const std::size_t limit = 64 * (fresh.size() + tris.size()) + 1024;
  for (std::size_t iteration = 0; !fresh.empty(); ++iteration) {
    if (iteration > limit) return fail(error, "cap: Delaunay restoration did not converge");
    const auto [a, b] = fresh.back();
    fresh.pop_back();
    Id s = -1;
    int i = -1;
    if (!find_edge(a, b, s, i)) continue;  // flipped away since
    const Tri& tri = tri_at(s);
    const Id ns = tri.n[i];
    if (ns < 0 || tri.w[i] != 0) continue;
    const Id c = tri.v[i];
    const Id d = tri_at(ns).v[opposite_index(ns, s)];
    if (incircle(p(tri.v[0]), p(tri.v[1]), p(tri.v[2]), p(d)) > 0) {
      flip(s, i);
      fresh.insert(fresh.end(), {{a, d}, {d, b}, {b, c}, {c, a}});
    }
  }
  return true;
}

/// Sloan's bin order: rows of bins, alternate rows right to left, so consecutive points are close.
void sort_by_bins(Workspace& ws, Id n, const Vec2& lo, double size) {
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
void randomize_rounds(Workspace& ws) {
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
  thread_local Workspace ws;
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
