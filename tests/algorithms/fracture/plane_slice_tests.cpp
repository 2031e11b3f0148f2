// plane-slice against answers known in closed form: volumes of cut polyhedra, areas of the caps,
// counts of disconnected parts; and the conservation figures on primitives.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace shatter;

namespace {

std::vector<Fragment> cut(const Mesh& solid, std::vector<Plane> planes) {
  auto result = PlaneSliceFracturer().fracture_by_planes(solid, planes);
  REQUIRE(result.ok());
  return std::move(*result);
}

double cut_area(const Fragment& f) { return tagged_area(f.mesh, FaceTag::cut); }

std::vector<double> sorted_volumes(const std::vector<Fragment>& fragments) {
  std::vector<double> v;
  for (const Fragment& f : fragments) v.push_back(f.mass.volume);
  std::sort(v.begin(), v.end());
  return v;
}

void require_closed(const std::vector<Fragment>& fragments) {
  for (const Fragment& f : fragments) {
    REQUIRE(is_closed_and_oriented(f.mesh));
    REQUIRE(all_finite(f.mesh));
    REQUIRE(f.mass.volume > 0);
  }
}

}  // namespace

TEST_CASE("plane-slice: unit cube cut through three of its vertices", "[plane-slice]") {
  const Mesh cube = test::make_unit_cube();
  const auto fragments = cut(cube, {{Vec3(1, 0, 0), Vec3(1, 1, 1)}});
  REQUIRE(fragments.size() == 2);
  require_closed(fragments);
  const auto v = sorted_volumes(fragments);
  CHECK(v[0] == Approx(1.0 / 6.0).epsilon(1e-12));
  CHECK(v[1] == Approx(5.0 / 6.0).epsilon(1e-12));
  // The cap is the equilateral triangle of side sqrt(2): area sqrt(3)/2, on both fragments.
  for (const Fragment& f : fragments) CHECK(cut_area(f) == Approx(std::sqrt(3.0) / 2.0).epsilon(1e-12));
}

TEST_CASE("plane-slice: unit cube cut along two opposite edges (the diagonal plane x = y)", "[plane-slice]") {
  const auto fragments = cut(test::make_unit_cube(), {{Vec3(0, 0, 0), Vec3(1, -1, 0)}});
  REQUIRE(fragments.size() == 2);
  require_closed(fragments);
  for (const Fragment& f : fragments) {
    CHECK(f.mass.volume == Approx(0.5).epsilon(1e-12));
    CHECK(cut_area(f) == Approx(std::sqrt(2.0)).epsilon(1e-12));  // a sqrt(2) x 1 rectangle
  }
}

TEST_CASE("plane-slice: a plane containing a face leaves the cube whole", "[plane-slice]") {
  for (const Plane& plane : {Plane{Vec3(0, 0, 1), Vec3(0, 0, 1)}, Plane{Vec3(0, 0, 1), Vec3(0, 0, -1)},
                             Plane{Vec3(0, 0, 0), Vec3(1, 0, 0)}}) {
    const auto fragments = cut(test::make_unit_cube(), {plane});
    REQUIRE(fragments.size() == 1);
    CHECK(fragments[0].mass.volume == Approx(1.0).epsilon(1e-14));
    CHECK(cut_area(fragments[0]) == 0.0);
  }
}

TEST_CASE("plane-slice: a plane through a face of a step cuts only the rest", "[plane-slice]") {
  // An L-shaped prism whose step face lies in the plane y = 1: only the tall arm is cut.
  const std::vector<Vec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const Mesh solid = test::extrude(l, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}, 0.0, 1.0);
  const auto fragments = cut(solid, {{Vec3(0, 1, 0), Vec3(0, 1, 0)}});
  REQUIRE(fragments.size() == 2);
  require_closed(fragments);
  const auto v = sorted_volumes(fragments);
  CHECK(v[0] == Approx(1.0).epsilon(1e-12));
  CHECK(v[1] == Approx(2.0).epsilon(1e-12));
  for (const Fragment& f : fragments) CHECK(cut_area(f) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("plane-slice: U shape cut across both arms gives three parts", "[plane-slice]") {
  const Mesh u = test::make_u_shape();
  Mesh copy = u;
  REQUIRE(validate_solid(copy, "u").ok());
  const auto fragments = cut(u, {{Vec3(0, 2, 0), Vec3(0, 1, 0)}});
  REQUIRE(fragments.size() == 3);
  require_closed(fragments);
  const auto v = sorted_volumes(fragments);
  CHECK(v[0] == Approx(1.0).epsilon(1e-12));
  CHECK(v[1] == Approx(1.0).epsilon(1e-12));
  CHECK(v[2] == Approx(5.0).epsilon(1e-12));
}

TEST_CASE("plane-slice: thick tube cut across has an annulus cap", "[plane-slice]") {
  const int n = 24;
  const Mesh tube = make_tube(0.5, 1.0, 2.0, n);
  const auto fragments = cut(tube, {{Vec3(0, 0, 0.3), Vec3(0, 0, 1)}});
  REQUIRE(fragments.size() == 2);
  require_closed(fragments);
  const double annulus = test::regular_polygon_area(n, 1.0) - test::regular_polygon_area(n, 0.5);
  for (const Fragment& f : fragments) CHECK(cut_area(f) == Approx(annulus).epsilon(1e-12));
  CHECK(fragments[0].mass.volume + fragments[1].mass.volume ==
        Approx(mass_properties(tube).volume).epsilon(1e-12));
}

TEST_CASE("plane-slice: torus cut through its axis has two loops per cap", "[plane-slice]") {
  const Mesh torus = make_torus(2.0, 0.5, 32, 16);
  const double volume = mass_properties(torus).volume;
  // A plane through the axis at a generic angle: the cap is two loops, one per side of the hole.
  const auto fragments = cut(torus, {{Vec3(0, 0, 0), Vec3(std::cos(0.3), std::sin(0.3), 0)}});
  REQUIRE(fragments.size() == 2);
  require_closed(fragments);
  CHECK(fragments[0].mass.volume + fragments[1].mass.volume == Approx(volume).epsilon(1e-12));
  // The torus is symmetric under the half turn about z, which maps each half onto the other.
  CHECK(fragments[0].mass.volume == Approx(fragments[1].mass.volume).epsilon(1e-9));
  CHECK(cut_area(fragments[0]) == Approx(cut_area(fragments[1])).epsilon(1e-12));
  CHECK(cut_area(fragments[0]) > 2 * test::regular_polygon_area(16, 0.5) * 0.99);
}

TEST_CASE("plane-slice: torus cut through its equator has a cap with a hole", "[plane-slice]") {
  const Mesh torus = make_torus(2.0, 0.5, 32, 16);
  const auto fragments = cut(torus, {{Vec3(0, 0, 0.1), Vec3(0, 0, 1)}});
  REQUIRE(fragments.size() == 2);
  require_closed(fragments);
  for (const Fragment& f : fragments) CHECK(cut_area(f) > 0.0);
  CHECK(cut_area(fragments[0]) == Approx(cut_area(fragments[1])).epsilon(1e-12));
  CHECK(fragments[0].mass.volume + fragments[1].mass.volume ==
        Approx(mass_properties(torus).volume).epsilon(1e-12));
}

TEST_CASE("plane-slice: recursive fracture of primitives conserves volume and partitions", "[plane-slice]") {
  const std::vector<Mesh> solids = {make_sphere(1.0, 32, 16), make_torus(2.0, 0.5, 48, 24),
                                    make_tube(0.5, 1.0, 2.0, 32), make_box(Vec3(4, 0.5, 0.5)),
                                    test::make_u_shape()};
  for (const Mesh& solid : solids) {
    const MassProperties mass = mass_properties(solid);
    for (int n : {5, 25, 100}) {
      FractureParams params;
      params.fragments = n;
      params.seed = 7;
      auto fragments = PlaneSliceFracturer().fracture(solid, params);
      REQUIRE(fragments.ok());
      CHECK(static_cast<int>(fragments->size()) >= n);
      require_closed(*fragments);
      const FractureMetrics m = fracture_metrics(solid, mass, *fragments, n);
      CHECK(m.volume_error <= 1e-9);
      CHECK(m.partition_error == 0.0);
      CHECK(m.area_error <= 1e-9);
      CHECK(m.all_closed);
    }
  }
}

TEST_CASE("plane-slice: the same seed gives the same fragments, another seed others", "[plane-slice]") {
  const Mesh sphere = make_sphere(1.0, 24, 12);
  FractureParams params;
  params.fragments = 20;
  params.seed = 42;
  auto a = PlaneSliceFracturer().fracture(sphere, params);
  auto b = PlaneSliceFracturer().fracture(sphere, params);
  params.seed = 43;
  auto c = PlaneSliceFracturer().fracture(sphere, params);
  REQUIRE((a.ok() && b.ok() && c.ok()));
  REQUIRE(a->size() == b->size());
  for (std::size_t i = 0; i < a->size(); ++i) {
    CHECK((*a)[i].mesh.vertices == (*b)[i].mesh.vertices);
    CHECK((*a)[i].mesh.triangles == (*b)[i].mesh.triangles);
  }
  CHECK(sorted_volumes(*a) != sorted_volumes(*c));
}

TEST_CASE("plane-slice: bad parameters are errors, not crashes", "[plane-slice]") {
  FractureParams params;
  params.fragments = 0;
  CHECK_FALSE(PlaneSliceFracturer().fracture(test::make_unit_cube(), params).ok());
  const std::vector<Plane> zero_normal = {{Vec3(0.5, 0.5, 0.5), Vec3::Zero()}};
  CHECK_FALSE(PlaneSliceFracturer().fracture_by_planes(test::make_unit_cube(), zero_normal).ok());
  const std::vector<Plane> nan_plane = {{Vec3(std::nan(""), 0, 0), Vec3::UnitX()}};
  CHECK_FALSE(PlaneSliceFracturer().fracture_by_planes(test::make_unit_cube(), nan_plane).ok());
}

TEST_CASE("plane-slice: a cut within rounding distance of an earlier cut never opens a piece", "[plane-slice]") {
  // A Voronoi cell piece whose earlier cut lies within rounding distance of the plane y = 0.0431...:
  // two outline points round to one position. The slicer must cut it into closed halves or find that
  // the plane misses it (the earlier cut's points within its snap distance), never fail or return
  // open halves. Fixture format: V F, V lines of hex-float x y z, F lines.
  std::FILE* f = std::fopen(SHATTER_SOURCE_DIR "/tests/fixtures/coincident_cut_piece.txt", "r");
  REQUIRE(f != nullptr);
  std::size_t nv = 0, nf = 0;
  REQUIRE(std::fscanf(f, "%zu %zu", &nv, &nf) == 2);
  Mesh piece;
  for (std::size_t i = 0; i < nv; ++i) {
    double x, y, z;
    REQUIRE(std::fscanf(f, "%la %la %la", &x, &y, &z) == 3);
    piece.add_vertex({x, y, z});
  }
  for (std::size_t i = 0; i < nf; ++i) {
    int a, b, c;
    REQUIRE(std::fscanf(f, "%d %d %d", &a, &b, &c) == 3);
    piece.add_triangle(a, b, c, FaceTag::surface);
  }
  std::fclose(f);
  REQUIRE(is_closed_and_oriented(piece));
  MeshSlicer slicer;
  Mesh below, above;
  const SliceOutcome outcome = slicer.slice(piece, {Vec3(0, 0.04318053211960312, 0), Vec3(0, 1, 0)}, below, above);
  REQUIRE(outcome != SliceOutcome::failed);
  if (outcome == SliceOutcome::cut) {
    CHECK(is_closed_and_oriented(below));
    CHECK(is_closed_and_oriented(above));
  }
}

TEST_CASE("plane-slice: explicit planes that make more pieces than the limit are refused", "[plane-slice][limits]") {
  // Three axis planes through the cube's centre make 8 pieces.
  const std::vector<Plane> planes = {
      {Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0)}, {Vec3(0.5, 0.5, 0.5), Vec3(0, 1, 0)}, {Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1)}};
  const Mesh cube = test::make_unit_cube();
  const auto eight = PlaneSliceFracturer().fracture_by_planes(cube, planes, 8);
  REQUIRE(eight.ok());
  CHECK(eight->size() == 8);
  const auto seven = PlaneSliceFracturer().fracture_by_planes(cube, planes, 7);
  REQUIRE_FALSE(seven.ok());
  CHECK_THAT(seven.error().message, Catch::StartsWith("plane-slice: the planes cut the solid into 8 pieces") &&
                                        Catch::Contains("exceeds the limit of 7 fragments"));
  // Stopped before the next plane once past the limit: 4 pieces after two planes.
  const auto three = PlaneSliceFracturer().fracture_by_planes(cube, planes, 3);
  REQUIRE_FALSE(three.ok());
  CHECK_THAT(three.error().message, Catch::Contains("more than 3 pieces (after 2 of 3 planes)"));
}
