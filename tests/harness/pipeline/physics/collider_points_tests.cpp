// collider_point_indices: a collider's points under a vertex budget. The truth it must keep: along
// each of its first directions (the 6 axes, 8 diagonals, 12 edge directions), the chosen points reach
// exactly as far as all the points do (the support function is unchanged there), and the chosen points
// are distinct points of the input, at most the budget.

#include "algorithms/core/primitives.h"
#include "harness/pipeline/physics/collider_points.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <set>

using namespace shatter;

namespace {

double support(const std::vector<Vec3>& points, const Vec3& d) {
  double best = -1e300;
  for (const Vec3& p : points) best = std::max(best, d.dot(p));
  return best;
}

}  // namespace

TEST_CASE("collider points: few points are all kept, in order", "[physics][colliders]") {
  const Mesh box = make_box(Vec3(1, 2, 3));
  const std::vector<std::int32_t> all = collider_point_indices(box.vertices, 8);
  REQUIRE(all.size() == box.vertices.size());
  for (std::size_t i = 0; i < all.size(); ++i) CHECK(all[i] == static_cast<std::int32_t>(i));
}

TEST_CASE("collider points: a budget keeps the extent along every cube direction", "[physics][colliders]") {
  const Mesh sphere = make_sphere(1.0, 40, 20, Vec3(0.3, -0.2, 5.0));
  REQUIRE(sphere.vertices.size() > 200);
  for (const int budget : {26, 32, 64}) {
    const std::vector<std::int32_t> chosen = collider_point_indices(sphere.vertices, budget);
    CHECK(static_cast<int>(chosen.size()) <= budget);
    CHECK(chosen.size() >= 20);  // the sphere's extremes are distinct along most directions
    const std::set<std::int32_t> distinct(chosen.begin(), chosen.end());
    CHECK(distinct.size() == chosen.size());
    std::vector<Vec3> kept;
    for (const std::int32_t v : chosen) {
      REQUIRE(v >= 0);
      REQUIRE(v < static_cast<std::int32_t>(sphere.vertices.size()));
      kept.push_back(sphere.vertices[static_cast<std::size_t>(v)]);
    }
    for (const std::array<double, 3> d : {std::array<double, 3>{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                          {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, {-1, -1, -1}, {1, -1, 1}, {0, 1, -1}}) {
      const Vec3 dir(d[0], d[1], d[2]);
      CHECK(support(kept, dir) == support(sphere.vertices, dir));
    }
  }
}

TEST_CASE("collider points: a budget above the cube's directions fills up with more extremes",
          "[physics][colliders]") {
  const Mesh sphere = make_sphere(1.0, 48, 24);
  const std::vector<std::int32_t> chosen = collider_point_indices(sphere.vertices, 48);
  // The Fibonacci directions after the first 26 find points the cube's directions missed.
  CHECK(chosen.size() > 26);
  CHECK(chosen.size() <= 48);
}

namespace {

/// The rule as stated, point by point: along each direction the first point with the largest d . p.
std::vector<std::int32_t> extremes_by_definition(const std::vector<Vec3>& points, const std::vector<Vec3>& directions,
                                                 std::size_t budget) {
  std::vector<std::int32_t> out;
  for (const Vec3& d : directions) {
    if (out.size() >= budget) break;
    std::size_t best = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
      if (d.dot(points[i]) > d.dot(points[best])) best = i;
    if (std::find(out.begin(), out.end(), static_cast<std::int32_t>(best)) == out.end())
      out.push_back(static_cast<std::int32_t>(best));
  }
  return out;
}

}  // namespace

TEST_CASE("collider points: each cube direction takes the first of its farthest points, ties included",
          "[physics][colliders]") {
  // A 4 x 4 x 4 grid of points (many ties along every cube direction) in a shuffled order, and a
  // sphere: with a budget of 26 only the cube's directions choose, so the choice is known point by point.
  std::vector<Vec3> grid;
  for (int i = 0; i < 64; ++i) grid.emplace_back((i * 7) % 4, (i * 13 / 4) % 4, (i * 5 / 16) % 4);
  const Mesh sphere = make_sphere(1.0, 24, 12, Vec3(0.1, 0.2, 0.3));
  std::vector<Vec3> cube_directions;
  for (const std::array<double, 3> d :
       {std::array<double, 3>{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1},
        {-1, -1, -1}, {1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {-1, 1, -1}, {-1, 1, 1}, {1, -1, -1}, {1, 1, 0},
        {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 0, 1}, {-1, 0, -1}, {1, 0, -1}, {-1, 0, 1}, {0, 1, 1},
        {0, -1, -1}, {0, 1, -1}, {0, -1, 1}})
    cube_directions.emplace_back(d[0], d[1], d[2]);
  for (const std::vector<Vec3>& points : {grid, sphere.vertices}) {
    CHECK(collider_point_indices(points, 26) == extremes_by_definition(points, cube_directions, 26));
    CHECK(collider_point_indices(points, 10) == extremes_by_definition(points, cube_directions, 10));
  }
}
