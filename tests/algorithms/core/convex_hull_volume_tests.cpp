// convex_hull_volume against independent volumes: a box and a tetrahedron by formula, a convex mesh by
// the divergence theorem over its own faces (mass_properties), interior points changing nothing.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/convex_hull_volume.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace shatter;

TEST_CASE("convex hull volume: boxes and a tetrahedron by formula", "[physics][colliders]") {
  const Mesh box = make_box(Vec3(1.5, 2.0, 0.25), Vec3(1e3, -2e3, 5e2));
  CHECK(convex_hull_volume(box.vertices) == Approx(0.75).epsilon(1e-12));
  const std::vector<Vec3> tet = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 3, 0), Vec3(0, 0, 4)};
  CHECK(convex_hull_volume(tet) == Approx(4.0).epsilon(1e-12));  // 2 * 3 * 4 / 6
  // Points inside add nothing.
  std::vector<Vec3> with_inside = tet;
  with_inside.push_back(Vec3(0.2, 0.3, 0.4));
  CHECK(convex_hull_volume(with_inside) == Approx(4.0).epsilon(1e-12));
}

TEST_CASE("convex hull volume: a convex mesh's hull is the mesh", "[physics][colliders]") {
  const Mesh sphere = make_sphere(0.7, 24, 12, Vec3(3, 4, 5));
  CHECK(convex_hull_volume(sphere.vertices) == Approx(mass_properties(sphere).volume).epsilon(1e-9));
}

TEST_CASE("convex hull volume: flat and tiny sets span no volume", "[physics][colliders]") {
  CHECK(convex_hull_volume(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) == 0.0);
  CHECK(convex_hull_volume(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}) == 0.0);
}
