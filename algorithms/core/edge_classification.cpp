#include "algorithms/core/edge_classification.h"

#include <algorithm>
#include <cmath>

namespace shatter {

EdgeClassification classify_edges(const std::vector<Triangle>& triangles, std::size_t vertex_count) {
  const std::size_t edge_count = 3 * triangles.size();
  std::vector<std::int32_t> lower(edge_count), upper(edge_count);
  std::vector<char> forward(edge_count);
  std::vector<std::int32_t> start(vertex_count + 1, 0);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t a = triangles[f][i], b = triangles[f][(i + 1) % 3];
      const std::size_t e = 3 * f + i;
      lower[e] = std::min(a, b);
      upper[e] = std::max(a, b);
      forward[e] = a < b;
      ++start[lower[e] + 1];
    }
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::int32_t> bucketed(edge_count), fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < edge_count; ++e) bucketed[fill[lower[e]]++] = static_cast<std::int32_t>(e);

  EdgeClassification result{std::vector<EdgeState>(edge_count), std::vector<std::int32_t>(edge_count),
                            std::vector<std::int32_t>(edge_count)};
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto first = bucketed.begin() + start[v], last = bucketed.begin() + start[v + 1];
    std::sort(first, last, [&](std::int32_t x, std::int32_t y) { return upper[x] < upper[y] || (upper[x] == upper[y] && x < y); });
    for (auto run = first; run != last;) {
      auto end = run;
      int forwards = 0;
      while (end != last && upper[*end] == upper[*run]) forwards += forward[*end++];
      const auto uses = static_cast<std::int32_t>(end - run);
      const EdgeState state = uses < 2   ? EdgeState::open
                              : uses > 2 ? EdgeState::non_manifold
                              : forwards != 1 ? EdgeState::misoriented
                                              : EdgeState::ok;
      for (auto it = run; it != end; ++it) {
        result.state[*it] = state;
        result.uses[*it] = uses;
        result.forwards[*it] = forwards;
      }
      run = end;
    }
  }
  return result;
}

namespace {

/// Shewchuk's two-sum and two-product: a + b and a * b as exact unevaluated sums hi + lo.
void two_sum(double a, double b, double& hi, double& lo) {
  hi = a + b;
  const double bv = hi - a;
  lo = (a - (hi - bv)) + (b - bv);
}

/// Adds `b` to the non-overlapping expansion `e` (Shewchuk's Grow-Expansion), keeping it exact.
void grow_expansion(std::vector<double>& e, double b) {
  double q = b;
  for (double& component : e) {
    double hi, lo;
    two_sum(q, component, hi, lo);
    component = lo;
    q = hi;
  }
  e.push_back(q);
}

/// Exact sign of ax*by - ay*bx + bx*cy - by*cx + cx*ay - cy*ax (orient2d, expanded so that no
/// rounded difference enters).
int exact_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double terms[6][2] = {{ax, by}, {-ay, bx}, {bx, cy}, {-by, cx}, {cx, ay}, {-cy, ax}};
  std::vector<double> e;
  e.reserve(13);
  for (const auto& t : terms) {
    const double p = t[0] * t[1];
    grow_expansion(e, p);
    grow_expansion(e, std::fma(t[0], t[1], -p));  // exact product error (barring underflow)
  }
  for (auto it = e.rbegin(); it != e.rend(); ++it)  // the largest non-zero component has the sign
    if (*it != 0.0) return *it > 0.0 ? 1 : -1;
  return 0;
}

}  // namespace

bool exactly_collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a;
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    // Floating-point filter (Shewchuk's ccwerrboundA): a clearly non-zero projection decides.
    const double left = u[i] * v[j], right = u[j] * v[i];
    if (std::abs(left - right) > 3.3306690738754716e-16 * (std::abs(left) + std::abs(right))) return false;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    if (exact_orient2d(a[i], a[j], b[i], b[j], c[i], c[j]) != 0) return false;
  }
  return true;
}


}  // namespace shatter
