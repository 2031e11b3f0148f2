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
