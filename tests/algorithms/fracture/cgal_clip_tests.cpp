// Tests of the cgal-clip reference fracturer against volumes and areas known in closed form.

#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"

#include "algorithms/core/mesh_validation.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace shatter {
namespace {


/// A U-shaped prism, z in [0, 1]: the polygon (0,0) (3,0) (3,2) (2,2) (2,1) (1,1) (1,2) (0,2), area 5.
/// Two legs x in [0,1] and [2,3] for y in [1,2] over a base y in [0,1].
Mesh u_prism() {
  const std::array<Vec2, 8> outline{Vec2(0, 0), Vec2(3, 0), Vec2(3, 2), Vec2(2, 2),
                                    Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};
  // Counter-clockwise triangles covering the polygon (checked by hand: areas sum to 5).
  const std::array<std::array<int, 3>, 6> cover{{{0, 1, 4}, {1, 2, 3}, {1, 3, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 7}}};
  Mesh m;
  for (const Vec2& p : outline) m.add_vertex(Vec3(p.x(), p.y(), 0.0));
  for (const Vec2& p : outline) m.add_vertex(Vec3(p.x(), p.y(), 1.0));
  for (const auto& t : cover) {
    m.add_triangle(t[0], t[2], t[1], FaceTag::surface);          // bottom, seen from below
    m.add_triangle(t[0] + 8, t[1] + 8, t[2] + 8, FaceTag::surface);  // top
  }
  for (int i = 0; i < 8; ++i) {
    const int j = (i + 1) % 8;
    m.add_triangle(i, j, j + 8, FaceTag::surface);
    m.add_triangle(i, j + 8, i + 8, FaceTag::surface);
  }
  return m;
}

/// Signed volume by the divergence theorem.
double volume(const Mesh& m) {
  double six = 0.0;
  for (const Triangle& t : m.triangles)
    six += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]]));
  return six / 6.0;
}

/// Total area of the triangles with `tag`.
double area(const Mesh& m, FaceTag tag) {
  double sum = 0.0;
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    if (m.tags[i] != tag) continue;
    const Triangle& t = m.triangles[i];
    sum += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
  }
  return sum;
}

/// Closed, 2-manifold along edges and consistently oriented (mesh_validation.h), one tag per triangle.
bool closed_and_oriented(const Mesh& m) {
  return m.tags.size() == m.triangles.size() && is_closed_and_oriented(m);
}

/// All coordinates finite.
bool finite(const Mesh& m) {
  for (const Vec3& p : m.vertices)
    if (!p.allFinite()) return false;
  return true;
}

std::vector<Fragment> cut(const Mesh& solid, std::vector<Plane> planes) {
  const CgalClipFracturer fracturer;
  Result<std::vector<Fragment>> result = fracturer.fracture_by_planes(solid, planes);
  REQUIRE(result.ok());
  return std::move(result).value();
}

}  // namespace

TEST_CASE("cgal-clip: unit cube cut at x = 0.3", "[cgal-clip]") {
  const std::vector<Fragment> f = cut(test::make_unit_cube(), {Plane{Vec3(0.3, 0.5, 0.5), Vec3(1, 0, 0)}});
  REQUIRE(f.size() == 2);
  // Below (x < 0.3) first.
  CHECK(volume(f[0].mesh) == Approx(0.3).epsilon(1e-14));
  CHECK(volume(f[1].mesh) == Approx(0.7).epsilon(1e-14));
  for (const Fragment& fragment : f) {
    CHECK(closed_and_oriented(fragment.mesh));
    CHECK(area(fragment.mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-14));
  }
  CHECK(area(f[0].mesh, FaceTag::surface) == Approx(4 * 0.3 + 1).epsilon(1e-14));
  CHECK(area(f[1].mesh, FaceTag::surface) == Approx(4 * 0.7 + 1).epsilon(1e-14));
  CHECK(f[0].mass.volume == Approx(0.3).epsilon(1e-14));
  CHECK(f[1].mass.volume == Approx(0.7).epsilon(1e-14));
  // Every cut vertex lies exactly on the plane.
  for (const Fragment& fragment : f)
    for (std::size_t i = 0; i < fragment.mesh.triangles.size(); ++i)
      if (fragment.mesh.tags[i] == FaceTag::cut)
        for (std::int32_t v : fragment.mesh.triangles[i]) CHECK(fragment.mesh.vertices[v].x() == 0.3);
}

TEST_CASE("cgal-clip: unit cube cut through three corners", "[cgal-clip]") {
  // x + y + z = 1 through (1,0,0), (0,1,0), (0,0,1): a corner tetrahedron of volume 1/6.
  const std::vector<Fragment> f = cut(test::make_unit_cube(), {Plane{Vec3(1, 0, 0), Vec3(1, 1, 1)}});
  REQUIRE(f.size() == 2);
  CHECK(volume(f[0].mesh) == Approx(1.0 / 6.0).epsilon(1e-14));
  CHECK(volume(f[1].mesh) == Approx(5.0 / 6.0).epsilon(1e-14));
  for (const Fragment& fragment : f) {
    CHECK(closed_and_oriented(fragment.mesh));
    CHECK(area(fragment.mesh, FaceTag::cut) == Approx(std::sqrt(3.0) / 2.0).epsilon(1e-14));
  }
}

TEST_CASE("cgal-clip: unit cube cut through two opposite edges", "[cgal-clip]") {
  // x = y contains the edges x = y = 0 and x = y = 1: two prisms of volume 1/2, caps sqrt(2) x 1.
  const std::vector<Fragment> f = cut(test::make_unit_cube(), {Plane{Vec3(0.5, 0.5, 0.5), Vec3(1, -1, 0)}});
  REQUIRE(f.size() == 2);
  for (const Fragment& fragment : f) {
    CHECK(volume(fragment.mesh) == Approx(0.5).epsilon(1e-14));
    CHECK(area(fragment.mesh, FaceTag::cut) == Approx(std::sqrt(2.0)).epsilon(1e-14));
    CHECK(area(fragment.mesh, FaceTag::surface) == Approx(3.0).epsilon(1e-14));
    CHECK(closed_and_oriented(fragment.mesh));
  }
  // Below is where x < y.
  CHECK(f[0].mesh.vertices[f[0].mesh.triangles[0][0]].y() >= f[0].mesh.vertices[f[0].mesh.triangles[0][0]].x());
}

TEST_CASE("cgal-clip: a plane containing a face leaves the cube whole", "[cgal-clip]") {
  const Vec3 normal = GENERATE(Vec3(1, 0, 0), Vec3(-1, 0, 0));
  const Vec3 point = GENERATE(Vec3(0, 0.2, 0.7), Vec3(1, 0.5, 0.5));
  const std::vector<Fragment> f = cut(test::make_unit_cube(), {Plane{point, normal}});
  REQUIRE(f.size() == 1);
  CHECK(volume(f[0].mesh) == Approx(1.0).epsilon(1e-15));
  CHECK(area(f[0].mesh, FaceTag::surface) == Approx(6.0).epsilon(1e-15));
  CHECK(area(f[0].mesh, FaceTag::cut) == 0.0);
  CHECK(closed_and_oriented(f[0].mesh));
}

TEST_CASE("cgal-clip: U prism cut across its legs gives three parts", "[cgal-clip]") {
  const std::vector<Fragment> f = cut(u_prism(), {Plane{Vec3(0, 1.5, 0), Vec3(0, 1, 0)}});
  REQUIRE(f.size() == 3);
  // Below: the base and the lower halves of the legs; above: the two leg tops, left first.
  CHECK(volume(f[0].mesh) == Approx(4.0).epsilon(1e-14));
  CHECK(volume(f[1].mesh) == Approx(0.5).epsilon(1e-14));
  CHECK(volume(f[2].mesh) == Approx(0.5).epsilon(1e-14));
  CHECK(f[1].mesh.vertices[f[1].mesh.triangles[0][0]].x() <= 1.0);
  CHECK(f[2].mesh.vertices[f[2].mesh.triangles[0][0]].x() >= 2.0);
  CHECK(area(f[0].mesh, FaceTag::cut) == Approx(2.0).epsilon(1e-14));
  CHECK(area(f[1].mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-14));
  CHECK(area(f[2].mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-14));
  for (const Fragment& fragment : f) CHECK(closed_and_oriented(fragment.mesh));
}

TEST_CASE("cgal-clip: a cut along a face of a non-convex solid keeps that face a surface face",
          "[cgal-clip]") {
  // y = 1 contains the bottom of the notch (x in [1,2], outward normal +y): the base below keeps it as
  // input surface, only x in [0,1] and [2,3] are cut.
  const Mesh u = u_prism();
  const std::vector<Fragment> f = cut(u, {Plane{Vec3(0, 1, 0), Vec3(0, 1, 0)}});
  REQUIRE(f.size() == 3);
  CHECK(volume(f[0].mesh) == Approx(3.0).epsilon(1e-14));
  CHECK(volume(f[1].mesh) == Approx(1.0).epsilon(1e-14));
  CHECK(volume(f[2].mesh) == Approx(1.0).epsilon(1e-14));
  CHECK(area(f[0].mesh, FaceTag::cut) == Approx(2.0).epsilon(1e-14));
  double surface = 0.0;
  for (const Fragment& fragment : f) {
    CHECK(closed_and_oriented(fragment.mesh));
    surface += area(fragment.mesh, FaceTag::surface);
  }
  CHECK(surface == Approx(area(u, FaceTag::surface)).epsilon(1e-14));
}

TEST_CASE("cgal-clip: random fracture partitions the volume and the surface", "[cgal-clip]") {
  const int fragments = GENERATE(5, 25);
  const std::uint64_t seed = GENERATE(1u, 7u);
  const Mesh solid = GENERATE(test::make_unit_cube(), u_prism());
  const CgalClipFracturer fracturer;
  Result<std::vector<Fragment>> result = fracturer.fracture(solid, FractureParams{fragments, seed, {}});
  REQUIRE(result.ok());
  const std::vector<Fragment>& f = result.value();
  CHECK(static_cast<int>(f.size()) >= fragments);
  double total = 0.0;
  double surface = 0.0;
  for (const Fragment& fragment : f) {
    CHECK(finite(fragment.mesh));
    CHECK(closed_and_oriented(fragment.mesh));
    const double v = volume(fragment.mesh);
    CHECK(v > 0.0);
    total += v;
    surface += area(fragment.mesh, FaceTag::surface);
  }
  const double input_volume = volume(solid);
  CHECK(std::abs(total - input_volume) <= 1e-12 * input_volume);
  const double input_area = area(solid, FaceTag::surface);
  CHECK(std::abs(surface - input_area) <= 1e-12 * input_area);
}

TEST_CASE("cgal-clip: same seed, same fragments", "[cgal-clip]") {
  const CgalClipFracturer fracturer;
  const FractureParams params{12, 3, {}};
  Result<std::vector<Fragment>> a = fracturer.fracture(u_prism(), params);
  Result<std::vector<Fragment>> b = fracturer.fracture(u_prism(), params);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  REQUIRE(a->size() == b->size());
  for (std::size_t i = 0; i < a->size(); ++i) {
    CHECK((*a)[i].mesh.vertices == (*b)[i].mesh.vertices);
    CHECK((*a)[i].mesh.triangles == (*b)[i].mesh.triangles);
    CHECK((*a)[i].mesh.tags == (*b)[i].mesh.tags);
  }
}

TEST_CASE("cgal-clip: bad parameters are errors", "[cgal-clip]") {
  const CgalClipFracturer fracturer;
  CHECK_FALSE(fracturer.fracture(test::make_unit_cube(), FractureParams{0, 1, {}}).ok());
  CHECK_FALSE(fracturer.fracture(Mesh{}, FractureParams{4, 1, {}}).ok());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Plane> not_finite{Plane{Vec3(nan, 0, 0), Vec3(1, 0, 0)}};
  CHECK_FALSE(fracturer.fracture_by_planes(test::make_unit_cube(), not_finite).ok());
  const std::vector<Plane> zero_normal{Plane{Vec3(0.5, 0.5, 0.5), Vec3::Zero()}};
  CHECK_FALSE(fracturer.fracture_by_planes(test::make_unit_cube(), zero_normal).ok());
}

TEST_CASE("cgal-clip: requests past the reference's size limit are refused at once", "[cgal-clip]") {
  const CgalClipFracturer fracturer;
  const Mesh cube = test::make_unit_cube();
  const auto many = fracturer.fracture(cube, FractureParams{kMaxReferenceFragments + 1, 1, {}});
  REQUIRE_FALSE(many.ok());
  CHECK(many.error().message == "cgal-clip: at most 250 fragments (the exact reference would run for minutes), got 251");
  std::vector<Plane> planes;
  for (int k = 0; k <= kMaxReferenceFragments; ++k) planes.push_back(Plane{Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0)});
  const auto by_planes = fracturer.fracture_by_planes(cube, planes);
  REQUIRE_FALSE(by_planes.ok());
  CHECK_THAT(by_planes.error().message, Catch::StartsWith("cgal-clip: at most 250 planes"));
  const std::vector<ConvexCell> cells(static_cast<std::size_t>(kMaxReferenceFragments) + 1);
  const auto by_cells = fracturer.fracture_by_cells(cube, cells);
  REQUIRE_FALSE(by_cells.ok());
  CHECK_THAT(by_cells.error().message, Catch::StartsWith("cgal-clip: at most 250 cells"));
  // At the limit itself the request is taken (cells without planes are cheap to run).
  CHECK(fracturer.fracture_by_cells(cube, std::span<const ConvexCell>(cells).first(kMaxReferenceFragments)).ok());
}

TEST_CASE("cgal-clip: a self-intersecting input is an error", "[cgal-clip]") {
  // Two overlapping cubes in one mesh: closed and oriented, but the surfaces cross.
  Mesh solid = test::make_unit_cube();
  const Mesh other = test::make_unit_cube();
  const auto offset = static_cast<std::int32_t>(solid.vertices.size());
  for (const Vec3& p : other.vertices) solid.add_vertex(p + Vec3(0.5, 0.25, 0.125));
  for (const Triangle& t : other.triangles) solid.add_triangle(t[0] + offset, t[1] + offset, t[2] + offset, FaceTag::surface);
  const CgalClipFracturer fracturer;
  const Result<std::vector<Fragment>> result = fracturer.fracture(solid, FractureParams{4, 1, {}});
  REQUIRE_FALSE(result.ok());
  CHECK(result.error().message.find("intersect") != std::string::npos);  // shells cross: they intersect
}

TEST_CASE("cgal-clip: is registered", "[cgal-clip]") {
  FracturerRegistry registry;
  register_cgal_clip(registry);
  Result<std::unique_ptr<Fracturer>> made = registry.create("cgal-clip");
  REQUIRE(made.ok());
  CHECK((*made)->name() == "cgal-clip");
  CHECK_FALSE(registry.description("cgal-clip").empty());
}

}  // namespace shatter
