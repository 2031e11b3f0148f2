// The convex-cap fan against independent truths: the analytic area of regular polygons (n/2 r^2
// sin(2 pi / n)), a triangulation that uses every outline edge once with the region on its left, and
// the loops it must decline (each is one a fan would cover wrongly).

#include "algorithms/fracture/plane_slice/convex_cap.h"

#include "algorithms/core/predicates.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

using shatter::CapEdge;
using shatter::Triangle;
using shatter::Vec2;

namespace {

std::vector<CapEdge> loop_edges(const std::vector<std::int32_t>& order) {
  std::vector<CapEdge> edges;
  for (std::size_t k = 0; k < order.size(); ++k) edges.push_back({order[k], order[(k + 1) % order.size()]});
  return edges;
}

std::vector<std::int32_t> iota_order(std::size_t n) {
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

std::vector<Vec2> regular_polygon(int n, double radius, Vec2 center = {0, 0}, double phase = 0.0) {
  std::vector<Vec2> r;
  for (int i = 0; i < n; ++i) {
    const double t = phase + 2.0 * M_PI * i / n;
    r.emplace_back(center.x() + radius * std::cos(t), center.y() + radius * std::sin(t));
  }
  return r;
}

double area(const std::vector<Vec2>& p, const Triangle& t) {
  const Vec2 a = p[static_cast<std::size_t>(t[0])], b = p[static_cast<std::size_t>(t[1])], c = p[static_cast<std::size_t>(t[2])];
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

/// Every outline edge appears once in the triangles, in its direction; every other directed edge
/// has its twin (no overlap, no gap).
void check_covers_outline(const std::vector<Triangle>& triangles, const std::vector<CapEdge>& edges) {
  std::map<std::pair<std::int32_t, std::int32_t>, int> half;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) ++half[{t[k], t[(k + 1) % 3]}];
  for (const CapEdge& e : edges) {
    REQUIRE(half[{e[0], e[1]}] == 1);
    half[{e[0], e[1]}] = 0;
  }
  for (const auto& [key, count] : half) {
    if (count == 0) continue;
    CHECK(count == 1);
    CHECK(half[{key.second, key.first}] == 1);
  }
}

}  // namespace

TEST_CASE("convex cap: regular polygons are fanned with their analytic area", "[cap]") {
  for (const int n : {3, 4, 7, 24, 200}) {
    for (const double radius : {1e-3, 1.0, 7.5e4}) {
      const std::vector<Vec2> points = regular_polygon(n, radius, {3.0 * radius, -2.0 * radius}, 0.3);
      const std::vector<CapEdge> edges = loop_edges(iota_order(points.size()));
      std::vector<Triangle> triangles;
      REQUIRE(shatter::fan_convex_cap(points, edges, triangles));
      REQUIRE(triangles.size() == static_cast<std::size_t>(n - 2));
      double sum = 0.0;
      for (const Triangle& t : triangles) {
        CHECK(shatter::orient2d(points[static_cast<std::size_t>(t[0])], points[static_cast<std::size_t>(t[1])],
                                points[static_cast<std::size_t>(t[2])]) > 0);
        sum += area(points, t);
      }
      const double exact = 0.5 * n * radius * radius * std::sin(2.0 * M_PI / n);
      CHECK(sum == Approx(exact).epsilon(1e-12));
      check_covers_outline(triangles, edges);
    }
  }
}

TEST_CASE("convex cap: edges given in any order and unused points are fine", "[cap]") {
  std::vector<Vec2> points = regular_polygon(9, 2.0);
  points.emplace_back(100.0, 100.0);  // no edge uses it
  std::vector<CapEdge> edges = loop_edges(iota_order(9));
  std::swap(edges[0], edges[5]);
  std::swap(edges[2], edges[8]);
  std::vector<Triangle> triangles;
  REQUIRE(shatter::fan_convex_cap(points, edges, triangles));
  CHECK(triangles.size() == 7);
  check_covers_outline(triangles, edges);
  for (const Triangle& t : triangles)
    for (const std::int32_t v : t) CHECK(v < 9);
}

TEST_CASE("convex cap: loops a fan would cover wrongly are declined", "[cap]") {
  std::vector<Triangle> untouched{{7, 7, 7}};
  const auto declined = [&](const std::vector<Vec2>& points, const std::vector<CapEdge>& edges) {
    std::vector<Triangle> triangles = untouched;
    const bool fanned = shatter::fan_convex_cap(points, edges, triangles);
    CHECK(triangles == untouched);
    return !fanned;
  };
  const std::vector<Vec2> hexagon = regular_polygon(6, 1.0);

  SECTION("clockwise: a hole with no outline") {
    std::vector<std::int32_t> order = iota_order(6);
    std::reverse(order.begin(), order.end());
    CHECK(declined(hexagon, loop_edges(order)));
  }
  SECTION("a reflex corner") {
    std::vector<Vec2> dart{{0, 0}, {4, 0}, {1, 1}, {0, 4}};  // (1, 1) turns right
    CHECK(declined(dart, loop_edges(iota_order(4))));
  }
  SECTION("three collinear corners") {
    std::vector<Vec2> square{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
    CHECK(declined(square, loop_edges(iota_order(5))));
  }
  SECTION("a pentagram: only left turns, but it winds twice") {
    const std::vector<Vec2> star = regular_polygon(5, 1.0);
    CHECK(declined(star, loop_edges({0, 2, 4, 1, 3})));
  }
  SECTION("a loop winding three times") {
    const std::vector<Vec2> star = regular_polygon(7, 1.0);
    CHECK(declined(star, loop_edges({0, 3, 6, 2, 5, 1, 4})));
  }
  SECTION("two loops, even both convex") {
    std::vector<Vec2> points = hexagon;
    for (const Vec2& p : regular_polygon(4, 1.0, {5.0, 0.0})) points.push_back(p);
    std::vector<CapEdge> edges = loop_edges(iota_order(6));
    for (const CapEdge& e : loop_edges({6, 7, 8, 9})) edges.push_back(e);
    CHECK(declined(points, edges));
  }
  SECTION("a point with two outgoing edges") {
    std::vector<CapEdge> edges = loop_edges(iota_order(6));
    edges.push_back({0, 3});
    edges.push_back({3, 0});
    CHECK(declined(hexagon, edges));
  }
  SECTION("an open chain") {
    std::vector<CapEdge> edges = loop_edges(iota_order(6));
    edges.pop_back();
    CHECK(declined(hexagon, edges));
  }
  SECTION("fewer than three edges, or a repeated point") {
    CHECK(declined(hexagon, {{0, 1}, {1, 0}}));
    std::vector<Vec2> points = hexagon;
    points.push_back(hexagon[2]);  // the same position under another index
    CHECK(declined(points, loop_edges({0, 1, 2, 6, 3, 4, 5})));
  }
  SECTION("magnitudes where the predicates lose exactness") {
    std::vector<Vec2> tiny = regular_polygon(6, 1e-130);
    CHECK(declined(tiny, loop_edges(iota_order(6))));
    std::vector<Vec2> huge = regular_polygon(6, 1e130);
    CHECK(declined(huge, loop_edges(iota_order(6))));
  }
}

namespace {

/// The independent truth: a loop is a strictly convex counter-clockwise polygon exactly when every
/// corner lies strictly left of every edge it is not an end of (O(n^2) exact orientation tests).
bool strictly_convex_by_all_pairs(const std::vector<Vec2>& points, const std::vector<std::int32_t>& order) {
  const std::size_t n = order.size();
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2& a = points[static_cast<std::size_t>(order[e])];
    const Vec2& b = points[static_cast<std::size_t>(order[(e + 1) % n])];
    for (std::size_t k = 0; k < n; ++k) {
      if (k == e || k == (e + 1) % n) continue;
      if (shatter::orient2d(a, b, points[static_cast<std::size_t>(order[k])]) <= 0) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("convex cap: accepted exactly when every corner is strictly left of every other edge", "[cap]") {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int accepted = 0, declined = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 30);
    std::vector<double> angles(static_cast<std::size_t>(n));
    for (double& a : angles) a = 2.0 * M_PI * unit(rng);
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> points;
    const int kind = trial % 4;
    for (int i = 0; i < n; ++i) {
      const double t = angles[static_cast<std::size_t>(i)];
      double r = 1.0;
      if (kind == 1) r = 0.6 + 0.4 * unit(rng);                     // star-shaped: often reflex
      if (kind == 2) r = 1.0 + 1e-15 * (unit(rng) - 0.5);           // convex up to round-off
      points.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    if (kind == 3) {  // points along the sides of a triangle: collinear in exact arithmetic or nearly
      points.clear();
      const Vec2 c[3] = {{0.0, 0.0}, {1.0, 0.1}, {0.3, 0.9}};
      for (int side = 0; side < 3; ++side)
        for (int k = 0; k < 1 + n / 3; ++k) {
          const double s = static_cast<double>(k) / (1 + n / 3);
          points.push_back((1.0 - s) * c[side] + s * c[(side + 1) % 3]);
        }
    }
    std::vector<std::int32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(rng() % order.size()), order.end());
    const bool duplicate = [&] {
      for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
          if (points[i] == points[j]) return true;
      return false;
    }();
    if (duplicate) continue;
    std::vector<Triangle> triangles;
    const bool fanned = shatter::fan_convex_cap(points, loop_edges(order), triangles);
    CHECK(fanned == strictly_convex_by_all_pairs(points, order));
    if (fanned) {
      ++accepted;
      check_covers_outline(triangles, loop_edges(order));
      for (const Triangle& t : triangles)
        CHECK(shatter::orient2d(points[static_cast<std::size_t>(t[0])], points[static_cast<std::size_t>(t[1])],
                                points[static_cast<std::size_t>(t[2])]) > 0);
    } else {
      ++declined;
    }
  }
  CHECK(accepted > 500);  // both outcomes are exercised
  CHECK(declined > 500);
}
