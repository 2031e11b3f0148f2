#include "algorithms/core/constrained_delaunay.h"

#include "algorithms/core/predicates.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace shatter::cdt {

/// Flips the edge opposite v[i] of t. t = (p, a, b), across it u = (q, b, a); afterwards
/// t = (p, a, q) and u = (q, b, p), both still holding p.
void Triangulation::flip(Id t, int i) {
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
Id Triangulation::locate(Id start, Id q, int& edge) {
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
void Triangulation::insert(Id q, Id& hint) {
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
bool Triangulation::find_edge(Id a, Id b, Id& t, int& i) const {
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
bool Triangulation::recover(Id u, Id v, Id weight, std::string& error) {
  Id from = u;
  // Each piece ends at a point further along u -> v, so there are fewer pieces than points; more
  // means the orientations were not consistent (coordinates beyond the predicates' exact range).
  for (std::size_t pieces = 0; from != v; ++pieces) {
    if (pieces > pts.size()) return fail(error, "cap: constraint recovery did not reach its end point");
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
        // The walk left the triangulation: the segment runs outside every triangle, which only
        // coordinates beyond the predicates' reach (a point 1e174 away) or a broken mesh make.
        if (nt < 0) return fail(error, "cap: constraint edge leaves the triangulation");
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
        if (!find_edge(ea, eb, s, i) || tri_at(s).n[i] < 0)
          return fail(error, "cap: constraint recovery lost a crossing edge");
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
    if (!find_edge(from, end, s, i)) return fail(error, "cap: constraint recovery did not make its edge");
    Tri& tri = tri_at(s);
    tri.w[i] += weight;
    link(s, i, tri.n[i], tri.w[i]);
    from = end;
  }
  return true;
}

/// Lawson flips on the edges made by constraint recovery, constraints excepted (Sloan's last step).
bool Triangulation::restore_delaunay(std::string& error) {
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

}  // namespace shatter::cdt
