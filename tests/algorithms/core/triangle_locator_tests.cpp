#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/core/triangle_locator.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace shatter;

namespace {

/// Squared distance from `p` to the nearest triangle, by trying every triangle.
double brute_force_distance2(const Mesh& mesh, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles) {
    const Vec3 q = closest_point_on_triangle(p, mesh.vertices[static_cast<std::size_t>(t[0])],
                                             mesh.vertices[static_cast<std::size_t>(t[1])],
                                             mesh.vertices[static_cast<std::size_t>(t[2])]);
    best = std::min(best, (q - p).squaredNorm());
  }
  return best;
}

}  // namespace

TEST_CASE("triangle locator: the closest point on a triangle in each Voronoi region", "[locator]") {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  CHECK(closest_point_on_triangle(Vec3(-1, -1, 3), a, b, c) == a);
  CHECK(closest_point_on_triangle(Vec3(3, -1, 1), a, b, c) == b);
  CHECK(closest_point_on_triangle(Vec3(-0.5, 4, 0), a, b, c) == c);
  CHECK(closest_point_on_triangle(Vec3(1, -2, 5), a, b, c).isApprox(Vec3(1, 0, 0)));
  CHECK(closest_point_on_triangle(Vec3(-3, 1, 0), a, b, c).isApprox(Vec3(0, 1, 0)));
  CHECK(closest_point_on_triangle(Vec3(2, 2, -1), a, b, c).isApprox(Vec3(1, 1, 0)));
  CHECK(closest_point_on_triangle(Vec3(0.5, 0.25, 7), a, b, c).isApprox(Vec3(0.5, 0.25, 0)));
  const Vec3 w = barycentric_coordinates(Vec3(0.5, 0.25, 7), a, b, c);
  CHECK(w.isApprox(Vec3(0.625, 0.25, 0.125)));
  CHECK(w.sum() == Approx(1.0));
}

TEST_CASE("triangle locator: the nearest triangle is as near as the brute-force one, inside, on and far off the mesh",
          "[locator]") {
  const Mesh torus = make_torus(1.0, 0.3, 48, 24);
  const TriangleLocator locate(torus);
  SplitMix64 rng(7);
  for (int i = 0; i < 400; ++i) {
    // Points near the surface, in the hole and far outside the grid.
    const double spread = i < 300 ? 1.5 : 40.0;
    const Vec3 p(rng.uniform(-spread, spread), rng.uniform(-spread, spread), rng.uniform(-spread / 3, spread / 3));
    const TriangleLocator::Hit hit = locate.nearest(p);
    REQUIRE(hit.triangle >= 0);
    CHECK(hit.distance2 == Approx(brute_force_distance2(torus, p)).epsilon(1e-12));
  }
  // A point on a triangle finds that triangle (or one as near: distance 0).
  for (std::size_t f = 0; f < torus.triangles.size(); f += 37) {
    const Triangle& t = torus.triangles[f];
    const Vec3 centroid = (torus.vertices[static_cast<std::size_t>(t[0])] + torus.vertices[static_cast<std::size_t>(t[1])] +
                           torus.vertices[static_cast<std::size_t>(t[2])]) /
                          3.0;
    const TriangleLocator::Hit hit = locate.nearest(centroid);
    CHECK(hit.triangle == static_cast<std::int32_t>(f));
    CHECK(hit.distance2 < 1e-28);
  }
}

TEST_CASE("triangle locator: only the included triangles are found, none gives no hit", "[locator]") {
  const Mesh box = make_box(Vec3(1, 1, 1));
  std::vector<std::uint8_t> include(box.triangles.size(), 0);
  include[4] = 1;
  const TriangleLocator one(box, include);
  CHECK(one.nearest(Vec3(10, 10, 10)).triangle == 4);
  std::vector<std::uint8_t> none(box.triangles.size(), 0);
  const TriangleLocator empty(box, none);
  CHECK(empty.nearest(Vec3(0, 0, 0)).triangle == -1);
}
