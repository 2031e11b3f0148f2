#include "algorithms/core/winding_number.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <span>

namespace shatter {
namespace {

constexpr double kInvFourPi = 0.25 * std::numbers::inv_pi;
// Tree leaves hold at most this many triangles.
constexpr int kLeafSize = 8;

// Solid angle of the triangle with corners a, b, c already relative to the query point.
// tan(omega / 2) = det[a b c] / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|) (Van Oosterom and
// Strackee 1983); atan2 keeps the quadrant, so omega covers (-2 pi, 2 pi).
double relative_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double det = a.dot(b.cross(c));
  // The point lies in the triangle's plane (or on a corner): the triangle is seen edge-on. Return
  // 0 rather than atan2(0, negative) = pi, whose sign would be arbitrary (see the header).
  if (det == 0.0) return 0.0;
  const double la = a.norm();
  const double lb = b.norm();
  const double lc = c.norm();
  const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  // det > 0 when the triangle's normal points away from the point, i.e. the point is behind it.
  return 2.0 * std::atan2(det, den);
}

}  // namespace

double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q) {
  return relative_solid_angle(a - q, b - q, c - q);
}

double winding_number(const Mesh& mesh, const Vec3& q) {
  assert(q.allFinite());
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles) {
    assert(t[0] >= 0 && t[1] >= 0 && t[2] >= 0);
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    sum += relative_solid_angle(a - q, b - q, c - q);
  }
  return sum * kInvFourPi;
}

WindingNumberQuery::WindingNumberQuery(const Mesh& mesh) {
  if (mesh.triangles.empty()) return;
  // Each triangle with its corner sum (3 x centroid, the split key) computed once: the median
  // splits then compare keys held beside the triangles instead of gathering three corners per
  // comparison.
  std::vector<Keyed> order(mesh.triangles.size());
  for (std::size_t f = 0; f < order.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    assert(std::all_of(t.begin(), t.end(), [&](std::int32_t v) { return v >= 0 && static_cast<std::size_t>(v) < mesh.vertices.size(); }));
    order[f] = {mesh.vertices[static_cast<std::size_t>(t[0])] + mesh.vertices[static_cast<std::size_t>(t[1])] +
                    mesh.vertices[static_cast<std::size_t>(t[2])],
                t};
  }
  nodes_.reserve(2 * (order.size() / kLeafSize + 1));
  nodes_.emplace_back();
  std::vector<Edge> boundary;
  boundary.reserve(4 * kLeafSize * 3);
  build(mesh, order, 0, 0, static_cast<int>(order.size()), boundary);
  closed_ = boundary.empty();
  bounds_ = nodes_[0].box;
  points_ = mesh.vertices;
  triangles_.reserve(order.size());
  for (const Keyed& k : order) triangles_.push_back(k.triangle);  // indices checked in build()
}

// Builds node `node` over order[begin, end) and its subtree; appends the node's boundary to `edges`:
// the net directed edges (an edge used as a->b twice and as b->a once is appended as a->b, count 1).
// `edges` is one stack for the whole build: a node's children append their boundaries, which the node
// replaces by its own in place, so no node allocates.
void WindingNumberQuery::build(const Mesh& mesh, std::vector<Keyed>& order, int node, int begin, int end,
                               std::vector<Edge>& edges) {
  const std::size_t base = edges.size();
  auto point = [&](std::int32_t v) -> const Vec3& {
    assert(v >= 0 && static_cast<std::size_t>(v) < mesh.vertices.size());
    return mesh.vertices[static_cast<std::size_t>(v)];
  };
  nodes_[static_cast<std::size_t>(node)].begin = begin;
  nodes_[static_cast<std::size_t>(node)].end = end;

  // A leaf's box is its corners'; an inner node's the union of its children's (the same box, with
  // no pass over the corners per level).
  if (end - begin <= kLeafSize) {
    Aabb box;
    for (int f = begin; f < end; ++f) {
      const Triangle& t = order[static_cast<std::size_t>(f)].triangle;
      for (const std::int32_t v : t) box.extend(point(v));
      for (int k = 0; k < 3; ++k) edges.push_back({t[k], t[(k + 1) % 3], 1});
    }
    nodes_[static_cast<std::size_t>(node)].box = box;
  } else {
    Aabb centroids;  // of the corner sums (3 x centroid)
    for (int f = begin; f < end; ++f) centroids.extend(order[static_cast<std::size_t>(f)].sum);
    // Median split of the centroids along the longest axis of their box.
    int axis = 0;
    (centroids.max - centroids.min).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [axis](const Keyed& a, const Keyed& b) { return a.sum[axis] < b.sum[axis]; });
    const int left = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    const int right = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    nodes_[static_cast<std::size_t>(node)].left = left;
    nodes_[static_cast<std::size_t>(node)].right = right;
    build(mesh, order, left, begin, mid, edges);
    build(mesh, order, right, mid, end, edges);
    Aabb box = nodes_[static_cast<std::size_t>(left)].box;
    box.extend(nodes_[static_cast<std::size_t>(right)].box.min);
    box.extend(nodes_[static_cast<std::size_t>(right)].box.max);
    nodes_[static_cast<std::size_t>(node)].box = box;
  }

  // Net multiplicity per undirected edge: +count for min->max, -count for max->min.
  for (std::size_t i = base; i < edges.size(); ++i) {
    Edge& e = edges[i];
    if (e.from > e.to) {
      std::swap(e.from, e.to);
      e.count = -e.count;
    }
  }
  std::sort(edges.begin() + static_cast<std::ptrdiff_t>(base), edges.end(),
            [](const Edge& a, const Edge& b) { return a.from != b.from ? a.from < b.from : a.to < b.to; });
  // Merged in place: the write position never passes the read position.
  std::size_t kept = base;
  int fan_size = 0;
  for (std::size_t i = base; i < edges.size();) {
    Edge net = edges[i];
    for (++i; i < edges.size() && edges[i].from == net.from && edges[i].to == net.to; ++i) net.count += edges[i].count;
    if (net.count == 0) continue;
    if (net.count < 0) {
      std::swap(net.from, net.to);
      net.count = -net.count;
    }
    edges[kept++] = net;
    fan_size += net.count;
  }
  edges.resize(kept);
  const std::span<const Edge> boundary(edges.data() + base, kept - base);

  // Inner node: keep the fan when it is cheaper than descending. Fan triangles through the apex
  // are degenerate (solid angle 0) and skipped.
  if (end - begin > kLeafSize && fan_size < end - begin) {
    Node& n = nodes_[static_cast<std::size_t>(node)];
    n.fan_begin = static_cast<int>(fans_.size());
    if (!boundary.empty()) {
      const std::int32_t apex = boundary.front().from;
      for (const Edge& e : boundary) {
        if (e.from == apex || e.to == apex) continue;
        for (int c = 0; c < e.count; ++c) fans_.push_back({apex, e.from, e.to});
      }
    }
    n.fan_end = static_cast<int>(fans_.size());
  }
}

double WindingNumberQuery::operator()(const Vec3& q) const {
  assert(q.allFinite());
  // Outside the box of a closed surface: exactly 0 (also covers a mesh without triangles, whose
  // box is empty and contains nothing).
  if (!bounds_.contains(q)) return 0.0;
  auto sum_over = [this, &q](const std::vector<Triangle>& triangles, int begin, int end) {
    double sum = 0.0;
    for (int i = begin; i < end; ++i) {
      const Triangle& t = triangles[static_cast<std::size_t>(i)];
      sum += relative_solid_angle(points_[static_cast<std::size_t>(t[0])] - q, points_[static_cast<std::size_t>(t[1])] - q,
                                  points_[static_cast<std::size_t>(t[2])] - q);
    }
    return sum;
  };
  // Depth-first; the median split keeps the depth below log2(#F) + 1, so 128 entries suffice.
  std::array<int, 128> stack;
  int top = 0;
  stack[top++] = 0;
  double sum = 0.0;
  while (top > 0) {
    const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
    if (n.left < 0) {
      sum += sum_over(triangles_, n.begin, n.end);
    } else if (n.fan_begin >= 0 && !n.box.contains(q)) {
      sum += sum_over(fans_, n.fan_begin, n.fan_end);
    } else {
      assert(top + 2 <= static_cast<int>(stack.size()));
      stack[top++] = n.right;
      stack[top++] = n.left;
    }
  }
  return sum * kInvFourPi;
}

}  // namespace shatter
