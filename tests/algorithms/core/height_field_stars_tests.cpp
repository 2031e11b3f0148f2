// Height-field stars: vertices whose triangles project one to one onto a coordinate plane. Checked on
// stars whose answer is known by construction (cones over a regular pentagon and over the pentagram,
// nested cones, folds, stars with faces along the axis), and on a fine sphere, where every star is a
// cap that deviates from its normal by a few degrees.

#include "algorithms/core/height_field_stars.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/self_intersection.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace shatter;

namespace {

/// A cone with apex 0 at (0, 0, height) over the regular n-gon of radius 1 in z = 0, its triangles
/// (apex, p_i, p_{i + step}) for i = 0, step, 2 step, ... until the link closes: step 1 is the pentagon's
/// cone, step 2 with n = 5 winds twice around the apex (the pentagram).
Mesh cone(int n, int step, double height, double radius = 1.0) {
  Mesh m;
  m.add_vertex({0, 0, height});
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n;
    m.add_vertex({radius * std::cos(angle), radius * std::sin(angle), 0});
  }
  int i = 0;
  do {
    const int j = (i + step) % n;
    m.add_triangle(0, 1 + i, 1 + j, FaceTag::surface);
    i = j;
  } while (i != 0);
  return m;
}

}  // namespace

TEST_CASE("height-field stars: cones known by construction", "[self-intersection]") {
  SECTION("a cone over a convex polygon projects one to one; its apex is a height field") {
    for (const double height : {0.01, 1.0, -3.0, 100.0}) {
      const Mesh m = cone(5, 1, height);
      CHECK(height_field_stars(m)[0] == 1);
      CHECK_FALSE(find_self_intersection(m));
    }
  }
  SECTION("a cone over the pentagram winds twice and meets itself along its apex's rays") {
    const Mesh m = cone(5, 2, 1.0);
    CHECK(height_field_stars(m)[0] == 0);
    const auto pair = find_self_intersection(m);
    REQUIRE(pair);
    // Every pair of this star shares the apex: the intersection is found among them.
    const Triangle& t = m.triangles[static_cast<std::size_t>((*pair)[0])];
    const Triangle& u = m.triangles[static_cast<std::size_t>((*pair)[1])];
    CHECK(t[0] == 0);
    CHECK(u[0] == 0);
  }
  SECTION("two nested cones on one apex: two link cycles, not a height field, and no intersection") {
    Mesh m = cone(6, 1, 1.0);
    const auto offset = static_cast<std::int32_t>(m.vertices.size()) - 1;  // the apex is shared
    const Mesh inner = cone(6, 1, 1.0, 0.5);
    for (std::size_t v = 1; v < inner.vertices.size(); ++v) m.add_vertex(inner.vertices[v]);
    for (const Triangle& t : inner.triangles) m.add_triangle(0, t[1] + offset, t[2] + offset, FaceTag::surface);
    CHECK(height_field_stars(m)[0] == 0);
    CHECK_FALSE(find_self_intersection(m));
  }
  SECTION("a fold: one triangle turned over its neighbours projects with the other orientation") {
    Mesh m = cone(6, 1, 1.0);
    std::swap(m.triangles[2][1], m.triangles[2][2]);
    CHECK(height_field_stars(m)[0] == 0);
  }
  SECTION("a star that turns back once: one clockwise wedge, one turn in all, overlapping wedges") {
    // Hexagon corners at 30 + 60 k degrees, link p0 p1 p2 p4 p3 p5: turns of +60 +60 +120 -60 +120 +60
    // degrees. The wedges (p2, p4) and (p4, p3) cover 210..270 degrees twice, so the star folds.
    Mesh m;
    m.add_vertex({0, 0, 1});
    for (int k = 0; k < 6; ++k) {
      const double angle = std::numbers::pi / 6 + std::numbers::pi / 3 * k;
      m.add_vertex({std::cos(angle), std::sin(angle), 0});
    }
    const int order[] = {0, 1, 2, 4, 3, 5};
    for (int k = 0; k < 6; ++k) m.add_triangle(0, 1 + order[k], 1 + order[(k + 1) % 6], FaceTag::surface);
    CHECK(height_field_stars(m)[0] == 0);
    CHECK(find_self_intersection(m));
  }
  SECTION("a flat star whose summed normal vanishes: every triangle projects to a segment") {
    // In z = 0, turning back on itself: the summed normal is 0, the axis x, and along x every triangle
    // is a segment. Two of its triangles overlap.
    Mesh m;
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(1, -1, 0), Vec3(1, 2, 0)}) m.add_vertex(p);
    m.add_triangle(0, 1, 2, FaceTag::surface);
    m.add_triangle(0, 2, 3, FaceTag::surface);
    m.add_triangle(0, 3, 1, FaceTag::surface);
    CHECK(height_field_stars(m)[0] == 0);
    CHECK(find_self_intersection(m));
  }
  SECTION("an open fan that spirals one and a quarter turns: the link is no permutation") {
    // Counter-clockwise wedges crossing +x once, as a closed star does, but the fan never closes: its
    // first and last quarter turns overlap.
    Mesh m;
    m.add_vertex({0, 0, 0});
    const int wedges = 6;
    for (int i = 0; i <= wedges; ++i) {
      const double angle = 2.5 * std::numbers::pi * i / wedges;
      const double radius = 1.0 + 0.1 * i;
      m.add_vertex({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    for (int i = 0; i < wedges; ++i) m.add_triangle(0, 1 + i, 2 + i, FaceTag::surface);
    CHECK(height_field_stars(m)[0] == 0);
    CHECK(find_self_intersection(m));
  }
  SECTION("a link edge used twice, and a star of fewer than three triangles") {
    Mesh m = cone(5, 1, 1.0);
    m.add_triangle(0, 1, 2, FaceTag::surface);
    CHECK(height_field_stars(m)[0] == 0);
    const std::vector<std::uint8_t> flags = height_field_stars(cone(5, 1, 1.0));
    for (std::size_t v = 1; v < flags.size(); ++v) CHECK(flags[v] == 0);  // two triangles each
  }
}

TEST_CASE("height-field stars: a box's corners have faces along every axis", "[self-intersection]") {
  // Each corner's star holds faces parallel to each axis, which project to segments: none qualifies,
  // and the pair test decides for them as before.
  for (const std::uint8_t flag : height_field_stars(make_box(Vec3(1, 2, 3)))) CHECK(flag == 0);
}

TEST_CASE("height-field stars: every star of a fine sphere", "[self-intersection]") {
  const Mesh sphere = make_sphere(2.0, 48, 24);
  const std::vector<std::uint8_t> flags = height_field_stars(sphere);
  REQUIRE(flags.size() == sphere.vertices.size());
  for (std::size_t v = 0; v < flags.size(); ++v) {
    INFO("vertex " << v);
    CHECK(flags[v] == 1);
  }
}
