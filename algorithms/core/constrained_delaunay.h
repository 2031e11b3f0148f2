#pragma once
/// The data structure of the constrained Delaunay triangulation behind triangulate_cap
/// (cap_triangulator.h), and its steps: point location, insertion, edge flips, constraint recovery.
///
/// Design note. Triangles live in one array; triangle t has vertices v[0..2] counter-clockwise,
/// n[i] = the triangle across the edge opposite v[i] (edge v[i+1] -> v[i+2]), -1 on the super
/// triangle's boundary, and w[i] = the net number of constraints running v[i+1] -> v[i+2] (the
/// neighbour holds -w). An edge with w != 0 is a constraint and is never flipped. Every predicate runs
/// on the exact input doubles (orient2d, incircle).

#include "algorithms/core/mesh.h"
#include "algorithms/core/predicates.h"

#include <cassert>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace shatter::cdt {

/// Index of a point or a triangle (-1: none).
using Id = std::int32_t;
/// `i` as an array index.
inline std::size_t at(Id i) { return static_cast<std::size_t>(i); }
/// The next and the previous corner of a triangle, counter-clockwise.
inline constexpr int kNext[3] = {1, 2, 0};
inline constexpr int kPrev[3] = {2, 0, 1};

/// One triangle: vertices, neighbours across the opposite edges, constraint weights of those edges.
struct Tri {
  Id v[3], n[3], w[3];
};

/// An undirected constraint u < v with the net count of u -> v minus v -> u edges.
struct Constraint {
  Id u, v, weight;
};

/// Sets `error` to `message`; false, for `return fail(...)`.
inline bool fail(std::string& error, const char* message) {
  error = message;
  return false;
}

/// The triangulation under construction: triangles with neighbours and constraint weights, and the
/// buffers of one call (reused across calls by the caller).
struct Triangulation {
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

  /// Flips the edge opposite v[i] of t.
  void flip(Id t, int i);
  /// The triangle holding point q, walking from `start`; `edge` = the edge q lies on, or -1.
  Id locate(Id start, Id q, int& edge);
  /// Inserts point q, keeping the triangulation Delaunay; `hint` is where the next walk starts.
  void insert(Id q, Id& hint);
  /// The triangle t whose edge i runs a -> b; false when there is none.
  bool find_edge(Id a, Id b, Id& t, int& i) const;
  /// Makes segment u -> v a constrained edge (split at points on it) with `weight` added; false with
  /// `error` when it crosses another constraint.
  bool recover(Id u, Id v, Id weight, std::string& error);
  /// Lawson flips on the edges made by recovery, constraints excepted.
  bool restore_delaunay(std::string& error);
};

}  // namespace shatter::cdt
