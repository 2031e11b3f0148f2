// Cap triangulator against independent truths: the shoelace area of the loops, the constraint edges
// present with the region on their left, no overlap (each directed edge used at most once), CCW
// triangles, and the empty-circle property on unconstrained interior edges.

#include "algorithms/core/cap_triangulator.h"

#include "algorithms/core/predicates.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

using shatter::CapEdge;
using shatter::Vec2;

namespace {

struct Loops {
  std::vector<Vec2> points;
  std::vector<CapEdge> edges;

  /// Appends a closed loop through the given points, in order.
  void add_loop(const std::vector<Vec2>& loop) {
    const auto first = static_cast<std::int32_t>(points.size());
    const auto n = static_cast<std::int32_t>(loop.size());
    points.insert(points.end(), loop.begin(), loop.end());
    for (std::int32_t i = 0; i < n; ++i) edges.push_back({first + i, first + (i + 1) % n});
  }
  /// Shoelace area: the integral of the winding number.
  [[nodiscard]] double shoelace() const {
    double area = 0.0;
    const Vec2 o = points.empty() ? Vec2(0, 0) : points[0];  // translation keeps it exact in math
    for (const CapEdge& e : edges) {
      const Vec2 a = points[static_cast<std::size_t>(e[0])] - o;
      const Vec2 b = points[static_cast<std::size_t>(e[1])] - o;
      area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    return area;
  }
};

std::vector<Vec2> rect(double x0, double y0, double x1, double y1, bool ccw = true) {
  std::vector<Vec2> r{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if (!ccw) std::reverse(r.begin(), r.end());
  return r;
}

std::vector<Vec2> regular_polygon(int n, double radius, Vec2 center = {0, 0}) {
  std::vector<Vec2> r;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n;
    r.emplace_back(center.x() + radius * std::cos(t), center.y() + radius * std::sin(t));
  }
  return r;
}

/// Runs the triangulator and checks every invariant; `edges_whole` asks that every input edge be a
/// triangle edge (false when points lie on edges, which split them).
void check_cap(const Loops& loops, bool edges_whole = true) {
  const auto result = shatter::triangulate_cap(loops.points, loops.edges);
  INFO(result.error << " points " << loops.points.size());
  REQUIRE(result.ok);
  const auto& pts = loops.points;
  std::map<std::pair<int, int>, int> directed;
  double area = 0.0;
  for (const auto& t : result.triangles) {
    const Vec2 &a = pts[static_cast<std::size_t>(t[0])], &b = pts[static_cast<std::size_t>(t[1])],
               &c = pts[static_cast<std::size_t>(t[2])];
    REQUIRE(shatter::orient2d(a, b, c) == 1);
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  const double expected = loops.shoelace();
  CHECK(area == Approx(expected).epsilon(1e-12).margin(1e-12));
  for (const auto& [edge, count] : directed) REQUIRE(count == 1);  // no overlap

  std::set<std::pair<int, int>> constraints;
  for (const CapEdge& e : loops.edges) constraints.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  if (edges_whole) {
    for (const CapEdge& e : loops.edges) {
      CHECK(directed.count({e[0], e[1]}) == 1);  // region on the left
      CHECK(directed.count({e[1], e[0]}) == 0);
    }
  }
  // Unconstrained interior edges are locally Delaunay.
  std::map<std::pair<int, int>, int> apex;
  for (const auto& t : result.triangles)
    for (int i = 0; i < 3; ++i) apex[{t[i], t[(i + 1) % 3]}] = t[(i + 2) % 3];
  for (const auto& [edge, c] : apex) {
    const auto other = apex.find({edge.second, edge.first});
    if (other == apex.end()) continue;
    if (constraints.count({std::min(edge.first, edge.second), std::max(edge.first, edge.second)})) continue;
    const auto P = [&](int i) { return pts[static_cast<std::size_t>(i)]; };
    REQUIRE(shatter::incircle(P(edge.first), P(edge.second), P(c), P(other->second)) <= 0);
  }
}

}  // namespace

TEST_CASE("cap: square", "[cap]") {
  Loops loops;
  loops.add_loop(rect(0, 0, 1, 1));
  check_cap(loops);
  CHECK(shatter::triangulate_cap(loops.points, loops.edges).triangles.size() == 2);
}

TEST_CASE("cap: square with a square hole", "[cap]") {
  Loops loops;
  loops.add_loop(rect(0, 0, 4, 4));
  loops.add_loop(rect(1, 1, 3, 3, false));
  REQUIRE(loops.shoelace() == 12.0);
  check_cap(loops);
}

TEST_CASE("cap: two disjoint squares", "[cap]") {
  Loops loops;
  loops.add_loop(rect(0, 0, 1, 1));
  loops.add_loop(rect(3, 0.5, 5, 2.5));
  check_cap(loops);
}

TEST_CASE("cap: island inside a hole inside a square", "[cap]") {
  Loops loops;
  loops.add_loop(rect(0, 0, 10, 10));
  loops.add_loop(rect(2, 2, 8, 8, false));
  loops.add_loop(rect(4, 4, 6, 6));
  REQUIRE(loops.shoelace() == 68.0);
  check_cap(loops);
}

TEST_CASE("cap: two squares touching at one vertex", "[cap]") {
  SECTION("shared index") {
    Loops loops;
    loops.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 1}, {2, 2}, {1, 2}};
    loops.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {4, 5}, {5, 6}, {6, 2}};
    check_cap(loops);
  }
  SECTION("duplicated point maps to the first index") {
    Loops loops;
    loops.add_loop(rect(0, 0, 1, 1));
    loops.add_loop(rect(1, 1, 2, 2));
    const auto result = shatter::triangulate_cap(loops.points, loops.edges);
    REQUIRE(result.ok);
    for (const auto& t : result.triangles)
      for (const auto i : t) CHECK(i != 4);  // (1, 1) again; index 2 stands for it
    Loops merged = loops;
    for (auto& e : merged.edges)
      for (auto& i : e)
        if (i == 4) i = 2;
    check_cap(merged);
  }
}

TEST_CASE("cap: squares sharing an edge merge (opposite edges cancel)", "[cap]") {
  Loops loops;
  loops.points = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
  loops.edges = {{0, 1}, {1, 4}, {4, 5}, {5, 0}, {1, 2}, {2, 3}, {3, 4}, {4, 1}};
  check_cap(loops, false);
  REQUIRE(loops.shoelace() == 2.0);
}

TEST_CASE("cap: comb-shaped concave polygon", "[cap]") {
  // Teeth [2k, 2k+1] x [1, 10] on a base [0, 21] x [0, 1]: area 21 + 11 * 9.
  std::vector<Vec2> comb{{0, 0}, {21, 0}, {21, 10}};
  for (int k = 10; k >= 1; --k) {
    comb.emplace_back(2 * k, 10);
    comb.emplace_back(2 * k, 1);
    comb.emplace_back(2 * k - 1, 1);
    comb.emplace_back(2 * k - 1, 10);
  }
  comb.emplace_back(0, 10);
  Loops loops;
  loops.add_loop(comb);
  REQUIRE(loops.shoelace() == 21.0 + 11.0 * 9.0);
  check_cap(loops);
}

TEST_CASE("cap: star-shaped polygon with deep spikes", "[cap]") {
  std::vector<Vec2> star;
  for (int i = 0; i < 40; ++i) {
    const double t = 2.0 * M_PI * i / 40;
    const double r = i % 2 == 0 ? 10.0 : 0.5;
    star.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  Loops loops;
  loops.add_loop(star);
  check_cap(loops);
}

TEST_CASE("cap: collinear vertices along the edges", "[cap]") {
  std::vector<Vec2> square;
  for (int i = 0; i < 8; ++i) square.emplace_back(i, 0);
  for (int i = 0; i < 8; ++i) square.emplace_back(8, i);
  for (int i = 8; i > 0; --i) square.emplace_back(i, 8);
  for (int i = 8; i > 0; --i) square.emplace_back(0, i);
  Loops loops;
  loops.add_loop(square);
  loops.add_loop({{2, 2}, {2, 6}, {4, 6}, {6, 6}, {6, 4}, {6, 2}, {4, 2}, {3, 2}});  // hole, clockwise
  REQUIRE(loops.shoelace() == 64.0 - 16.0);
  check_cap(loops);
}

TEST_CASE("cap: point of another loop lying on a constraint splits it", "[cap]") {
  Loops loops;
  loops.add_loop(rect(0, 0, 4, 4));
  loops.add_loop({{2, 0}, {1, 1}, {3, 1}});  // clockwise hole touching the bottom edge at (2, 0)
  REQUIRE(loops.shoelace() == 15.0);
  check_cap(loops, false);
}

TEST_CASE("cap: regular 1000-gon", "[cap]") {
  Loops loops;
  loops.add_loop(regular_polygon(1000, 3.0, {1e3, -2e3}));
  check_cap(loops);
}

TEST_CASE("cap: random star-shaped polygons", "[cap]") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int round = 0; round < 30; ++round) {
    // Stratified angles keep every angular gap below pi: the origin sees every edge, so the polygon
    // is simple and star-shaped around it.
    const int n = 4 + static_cast<int>(unit(rng) * 300);
    std::vector<Vec2> star;
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * M_PI * (i + 0.9 * unit(rng)) / n;
      const double r = 0.1 + unit(rng);
      star.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    Loops loops;
    loops.add_loop(star);
    check_cap(loops);
  }
}

TEST_CASE("cap: square with many random holes", "[cap]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Loops loops;
  loops.add_loop(rect(0, 0, 40, 40));
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      if (unit(rng) < 0.4) {
        const double s = 0.1 + 0.3 * unit(rng);
        loops.add_loop(rect(i + 0.5 - s, j + 0.5 - s, i + 0.5 + s, j + 0.5 + s, false));
      }
  check_cap(loops);
}

TEST_CASE("cap: random sets of grid cells", "[cap]") {
  // The boundary of a union of unit cells, as unit edges: many collinear and cocircular points, loops
  // touching at vertices (checkerboard corners), holes and islands. Area = the number of cells.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = 24;
  for (int round = 0; round < 10; ++round) {
    const double fill = 0.2 + 0.06 * round;
    std::vector<char> in(static_cast<std::size_t>(n * n));
    for (auto& c : in) c = unit(rng) < fill;
    const auto cell = [&](int i, int j) {
      return i >= 0 && j >= 0 && i < n && j < n && in[static_cast<std::size_t>(i * n + j)];
    };
    const auto id = [&](int i, int j) { return i * (n + 1) + j; };  // grid point (i, j)
    Loops loops;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) loops.points.emplace_back(i * 0.1, j * 0.1);
    int cells = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (!cell(i, j)) continue;
        ++cells;
        if (!cell(i, j - 1)) loops.edges.push_back({id(i, j), id(i + 1, j)});
        if (!cell(i + 1, j)) loops.edges.push_back({id(i + 1, j), id(i + 1, j + 1)});
        if (!cell(i, j + 1)) loops.edges.push_back({id(i + 1, j + 1), id(i, j + 1)});
        if (!cell(i - 1, j)) loops.edges.push_back({id(i, j + 1), id(i, j)});
      }
    CHECK(loops.shoelace() == Approx(cells * 0.01).epsilon(1e-12));
    check_cap(loops);
  }
}

TEST_CASE("cap: degenerate input is ignored", "[cap]") {
  Loops loops;
  loops.add_loop(rect(0, 0, 2, 2));
  loops.points.emplace_back(1, 1);   // unused point
  loops.points.emplace_back(0, 0);   // duplicate of point 0
  loops.edges.push_back({1, 1});     // zero-length edges
  loops.edges.push_back({0, 5});
  check_cap(loops, false);
  CHECK(shatter::triangulate_cap(loops.points, {}).triangles.empty());
  const std::vector<Vec2> line{{0, 0}, {1, 1}, {2, 2}};
  const std::vector<CapEdge> back_and_forth{{0, 1}, {1, 2}, {2, 1}, {1, 0}};
  const auto flat = shatter::triangulate_cap(line, back_and_forth);
  CHECK(flat.ok);
  CHECK(flat.triangles.empty());
}

TEST_CASE("cap: crossing constraints are reported", "[cap]") {
  Loops overlap;
  overlap.add_loop(rect(0, 0, 2, 2));
  overlap.add_loop(rect(1, 1, 3, 3));
  const auto a = shatter::triangulate_cap(overlap.points, overlap.edges);
  CHECK_FALSE(a.ok);
  CHECK_FALSE(a.error.empty());

  Loops bowtie;
  bowtie.add_loop({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  const auto b = shatter::triangulate_cap(bowtie.points, bowtie.edges);
  CHECK_FALSE(b.ok);
}
