#include "algorithms/core/winding_number.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

namespace shatter {
namespace {

// Closed outward prism: the counter-clockwise polygon `outline` (xy) extruded from z0 to z1. The caps
// are fans from `fan_apex` (an outline index that sees every other corner).
Mesh make_prism(const std::vector<Vec2>& outline, double z0, double z1, int fan_apex = 0) {
  Mesh mesh;
  const int n = static_cast<int>(outline.size());
  for (const Vec2& p : outline) mesh.add_vertex({p.x(), p.y(), z0});
  for (const Vec2& p : outline) mesh.add_vertex({p.x(), p.y(), z1});
  for (int k = 1; k + 1 < n; ++k) {
    const int b = (fan_apex + k) % n;
    const int c = (fan_apex + k + 1) % n;
    mesh.add_triangle(n + fan_apex, n + b, n + c, FaceTag::surface);  // top, normal +z
    mesh.add_triangle(fan_apex, c, b, FaceTag::surface);              // bottom, normal -z
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.add_triangle(i, j, n + j, FaceTag::surface);  // side, normal to the right of edge i -> j
    mesh.add_triangle(i, n + j, n + i, FaceTag::surface);
  }
  return mesh;
}

// Axis-aligned box [lo, hi], outward.
Mesh make_test_box(const Vec3& lo, const Vec3& hi) {
  return make_prism({{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}}, lo.z(), hi.z());
}

// Same surface with every triangle reversed (an inward mesh).
Mesh reversed(Mesh mesh) {
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// Union of two meshes (vertex indices of `b` shifted).
Mesh merged(const Mesh& a, const Mesh& b) {
  Mesh out = a;
  const auto offset = static_cast<std::int32_t>(a.vertices.size());
  for (const Vec3& p : b.vertices) out.add_vertex(p);
  for (std::size_t f = 0; f < b.triangles.size(); ++f) {
    const Triangle& t = b.triangles[f];
    out.add_triangle(t[0] + offset, t[1] + offset, t[2] + offset, b.tags[f]);
  }
  return out;
}

// UV sphere of radius 1 at the origin, outward; `soup` gives every triangle its own corners (no
// shared indices), so the query's boundary fans cannot shortcut anything.
Mesh make_test_sphere(int segments, int rings, bool soup) {
  Mesh grid;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const double theta = std::numbers::pi * r / rings;
      const double phi = 2.0 * std::numbers::pi * s / segments;
      grid.add_vertex({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  }
  // The poles are repeated per segment: snap them to one index each so the mesh is closed.
  auto id = [&](int r, int s) { return r == 0 ? 0 : r == rings ? rings * segments : r * segments + s % segments; };
  Mesh mesh;
  mesh.vertices = grid.vertices;
  auto add = [&](int a, int b, int c) {
    if (!soup) return mesh.add_triangle(a, b, c, FaceTag::surface);
    const auto i = mesh.add_vertex(grid.vertices[static_cast<std::size_t>(a)]);
    mesh.add_vertex(grid.vertices[static_cast<std::size_t>(b)]);
    mesh.add_vertex(grid.vertices[static_cast<std::size_t>(c)]);
    mesh.add_triangle(i, i + 1, i + 2, FaceTag::surface);
  };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      if (r > 0) add(id(r, s), id(r + 1, s), id(r, s + 1));
      if (r + 1 < rings) add(id(r, s + 1), id(r + 1, s), id(r + 1, s + 1));
    }
  }
  return mesh;
}

constexpr double kTol = 1e-12;

}  // namespace

TEST_CASE("winding-number: solid angle of a cube face seen from the centre is 4 pi / 6", "[winding-number]") {
  // Two triangles of the face z = 1 of the cube [-1, 1]^3, outward; the centre is behind them.
  const Vec3 q = Vec3::Zero();
  const double omega = triangle_solid_angle({-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, q) +
                       triangle_solid_angle({-1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, q);
  CHECK(omega == Approx(4.0 * std::numbers::pi / 6.0).margin(kTol));
  // Seen from the other side the sign flips.
  CHECK(triangle_solid_angle({-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {0, 0, 2}) < 0.0);
  // Seen from its own plane: 0, even from inside the triangle.
  CHECK(triangle_solid_angle({-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {0.5, -0.5, 1}) == 0.0);
}

TEST_CASE("winding-number: unit box is 1 inside and 0 outside", "[winding-number]") {
  const Mesh box = make_test_box({0, 0, 0}, {1, 1, 1});
  const WindingNumberQuery query(box);
  const std::vector<Vec3> inside = {{0.5, 0.5, 0.5}, {0.01, 0.02, 0.03}, {0.999, 0.5, 0.001}, {0.3, 0.9, 0.7}};
  const std::vector<Vec3> outside = {{1.5, 0.5, 0.5}, {-0.01, 0.5, 0.5}, {0.5, 0.5, 1.001}, {2, 2, 2}};
  for (const Vec3& p : inside) {
    CHECK(winding_number(box, p) == Approx(1.0).margin(kTol));
    CHECK(query(p) == Approx(1.0).margin(kTol));
  }
  for (const Vec3& p : outside) {
    CHECK(winding_number(box, p) == Approx(0.0).margin(kTol));
    CHECK(query(p) == 0.0);  // outside the box: exactly 0
  }
  // Far away: the free function still sums to round-off, the query answers exactly.
  CHECK(winding_number(box, {1e6, -3e6, 2e6}) == Approx(0.0).margin(kTol));
  CHECK(query({1e6, -3e6, 2e6}) == 0.0);
  CHECK(query.bounds().min == Vec3(0, 0, 0));
  CHECK(query.bounds().max == Vec3(1, 1, 1));
  CHECK(query.triangle_count() == 12);
}

TEST_CASE("winding-number: on the surface it is the inside share of a small sphere", "[winding-number]") {
  const Mesh box = make_test_box({0, 0, 0}, {1, 1, 1});
  const WindingNumberQuery query(box);
  CHECK(query({0.5, 0.5, 1.0}) == Approx(0.5).margin(kTol));    // face centre (on a diagonal)
  CHECK(query({0.2, 0.0, 0.6}) == Approx(0.5).margin(kTol));    // inside a face
  CHECK(query({0.5, 0.0, 0.0}) == Approx(0.25).margin(kTol));   // edge: a quarter
  CHECK(query({1.0, 1.0, 1.0}) == Approx(0.125).margin(kTol));  // corner: an eighth
  CHECK(winding_number(box, {0.0, 0.0, 0.0}) == Approx(0.125).margin(kTol));
}

TEST_CASE("winding-number: reversed box gives -1 inside", "[winding-number]") {
  const Mesh box = reversed(make_test_box({0, 0, 0}, {1, 1, 1}));
  CHECK(winding_number(box, {0.5, 0.5, 0.5}) == Approx(-1.0).margin(kTol));
  CHECK(WindingNumberQuery(box)({0.2, 0.7, 0.4}) == Approx(-1.0).margin(kTol));
  CHECK(winding_number(box, {1.5, 0.5, 0.5}) == Approx(0.0).margin(kTol));
}

TEST_CASE("winding-number: L-shaped prism is 0 in the notch", "[winding-number]") {
  // L = [0,2]x[0,1] union [0,1]x[1,2], extruded over z in [0,1]; the caps fan from the reflex
  // corner (1, 1), which sees every other corner.
  const std::vector<Vec2> outline = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const Mesh l_shape = make_prism(outline, 0.0, 1.0, 3);
  REQUIRE(l_shape.triangle_count() == 20);
  const WindingNumberQuery query(l_shape);
  for (const Vec3& p : {Vec3(0.5, 0.5, 0.5), Vec3(1.5, 0.5, 0.5), Vec3(0.5, 1.5, 0.5), Vec3(1.9, 0.9, 0.1)}) {
    CHECK(winding_number(l_shape, p) == Approx(1.0).margin(kTol));
    CHECK(query(p) == Approx(1.0).margin(kTol));
  }
  // The notch [1,2]x[1,2] is inside the bounding box but outside the solid.
  for (const Vec3& p : {Vec3(1.5, 1.5, 0.5), Vec3(1.01, 1.01, 0.99), Vec3(1.99, 1.99, 0.01)}) {
    CHECK(query.bounds().contains(p));
    CHECK(winding_number(l_shape, p) == Approx(0.0).margin(kTol));
    CHECK(query(p) == Approx(0.0).margin(kTol));
  }
}

TEST_CASE("winding-number: hollow box is 0 in the cavity, and overlapping shells add up", "[winding-number]") {
  const Mesh outer = make_test_box({0, 0, 0}, {3, 3, 3});
  const Mesh cavity = reversed(make_test_box({1, 1, 1}, {2, 2, 2}));
  const WindingNumberQuery shell(merged(outer, cavity));
  CHECK(shell({0.5, 1.5, 1.5}) == Approx(1.0).margin(kTol));  // in the wall
  CHECK(shell({1.5, 1.5, 1.5}) == Approx(0.0).margin(kTol));  // in the cavity
  CHECK(shell({2.5, 2.5, 2.5}) == Approx(1.0).margin(kTol));

  const Mesh twice = merged(outer, make_test_box({1, 1, 1}, {2, 2, 2}));
  CHECK(winding_number(twice, {1.5, 1.5, 1.5}) == Approx(2.0).margin(kTol));
  CHECK(winding_number(twice, {0.5, 0.5, 0.5}) == Approx(1.0).margin(kTol));
}

TEST_CASE("winding-number: the tree query is exact on a large sphere", "[winding-number]") {
  // 2 x 64 x 63 triangles. The polyhedron contains the ball of radius cos(pi / 32) > 0.99 and lies
  // in the unit ball, so points with |p| < 0.98 are inside and |p| > 1.01 outside (the corners of
  // the bounding box are outside the sphere but inside the box: the tree has to decide them).
  for (const bool soup : {false, true}) {
    const Mesh sphere = make_test_sphere(64, 64, soup);
    REQUIRE(sphere.triangle_count() == 2 * 64 * 63);
    const WindingNumberQuery query(sphere);
    std::uint64_t state = 7;
    auto uniform = [&state] {  // a tiny LCG: any spread of points will do
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<double>(state >> 11) * 0x1.0p-53 * 2.0 - 1.0;
    };
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
      const Vec3 p(uniform(), uniform(), uniform());
      const double r = p.norm();
      if (r > 0.98 && r < 1.01) continue;
      const double expected = r < 0.98 ? 1.0 : 0.0;
      CHECK(query(p) == Approx(expected).margin(1e-10));
      CHECK(winding_number(sphere, p) == Approx(expected).margin(1e-10));
      ++checked;
    }
    CHECK(checked > 300);
    CHECK(query({0, 0, 0}) == Approx(1.0).margin(1e-10));
    CHECK(query({0.99, 0.99, 0.99}) == Approx(0.0).margin(1e-10));
  }
}

TEST_CASE("winding-number: a mesh without triangles is 0 everywhere", "[winding-number]") {
  const Mesh empty;
  CHECK(winding_number(empty, Vec3::Zero()) == 0.0);
  const WindingNumberQuery query(empty);
  CHECK(query(Vec3::Zero()) == 0.0);
  CHECK(query.bounds().diagonal() == 0.0);
}

}  // namespace shatter
