// Tests of cgal-clip's exact cell fracture (fracture_by_cells) against volumes and areas known in
// closed form.

#include "algorithms/core/mass_properties.h"
#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/recursive_slicing.h"
#include "algorithms/core/mesh_validation.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace shatter {
namespace {


/// The half-space {x : dot(normal, x - point) <= 0}.
Plane below(Vec3 point, Vec3 normal) { return Plane{point, normal}; }

/// Closed, 2-manifold along edges and consistently oriented (mesh_validation.h), one tag per triangle.
bool closed_and_oriented(const Mesh& m) {
  return m.tags.size() == m.triangles.size() && is_closed_and_oriented(m);
}

std::vector<Fragment> fracture(const Mesh& solid, const std::vector<ConvexCell>& cells) {
  const CgalClipFracturer fracturer;
  Result<std::vector<Fragment>> result = fracturer.fracture_by_cells(solid, cells);
  INFO((result.ok() ? std::string() : result.error().message));
  REQUIRE(result.ok());
  return std::move(result).value();
}

/// Centroid projections along part_order_direction() never decrease.
bool in_part_order(const std::vector<Fragment>& f) {
  for (std::size_t i = 1; i < f.size(); ++i)
    if (f[i].mass.centroid.dot(part_order_direction()) < f[i - 1].mass.centroid.dot(part_order_direction()))
      return false;
  return true;
}

}  // namespace

TEST_CASE("cgal-cells: unit cube in the half-space x <= 0.3", "[cgal-cells]") {
  const std::vector<Fragment> f = fracture(test::make_unit_cube(), {ConvexCell{{below(Vec3(0.3, 0, 0), Vec3(1, 0, 0))}}});
  REQUIRE(f.size() == 1);
  CHECK(signed_volume(f[0].mesh) == Approx(0.3).epsilon(1e-14));
  CHECK(tagged_area(f[0].mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-14));
  CHECK(tagged_area(f[0].mesh, FaceTag::surface) == Approx(4 * 0.3 + 1).epsilon(1e-14));
  CHECK(closed_and_oriented(f[0].mesh));
  for (std::size_t i = 0; i < f[0].mesh.triangles.size(); ++i)
    if (f[0].mesh.tags[i] == FaceTag::cut)
      for (std::int32_t v : f[0].mesh.triangles[i]) CHECK(f[0].mesh.vertices[v].x() == 0.3);
}

TEST_CASE("cgal-cells: unit cube in the octant below (0.5, 0.5, 0.5)", "[cgal-cells]") {
  const Vec3 c(0.5, 0.5, 0.5);
  const std::vector<Fragment> f = fracture(
      test::make_unit_cube(), {ConvexCell{{below(c, Vec3(1, 0, 0)), below(c, Vec3(0, 1, 0)), below(c, Vec3(0, 0, 1))}}});
  REQUIRE(f.size() == 1);
  CHECK(signed_volume(f[0].mesh) == Approx(0.125).epsilon(1e-14));
  CHECK(tagged_area(f[0].mesh, FaceTag::cut) == Approx(3 * 0.25).epsilon(1e-14));
  CHECK(tagged_area(f[0].mesh, FaceTag::surface) == Approx(3 * 0.25).epsilon(1e-14));
  CHECK(closed_and_oriented(f[0].mesh));
}

TEST_CASE("cgal-cells: two complementary cells split the cube exactly", "[cgal-cells]") {
  const std::vector<Fragment> f = fracture(test::make_unit_cube(), {ConvexCell{{below(Vec3(0.3, 0, 0), Vec3(1, 0, 0))}},
                                                         ConvexCell{{below(Vec3(0.3, 0, 0), Vec3(-1, 0, 0))}}});
  REQUIRE(f.size() == 2);
  CHECK(f[0].mass.volume == Approx(0.3).epsilon(1e-14));
  CHECK(f[1].mass.volume == Approx(0.7).epsilon(1e-14));
  CHECK(std::abs(f[0].mass.volume + f[1].mass.volume - 1.0) <= 1e-12);
  for (const Fragment& fragment : f) {
    CHECK(tagged_area(fragment.mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-14));
    CHECK(closed_and_oriented(fragment.mesh));
  }
}

TEST_CASE("cgal-cells: a cell across the arms of a U gives two parts in part order", "[cgal-cells]") {
  // y >= 2 keeps the tops of both arms, [0,1]x[2,3] and [2,3]x[2,3].
  const std::vector<Fragment> f =
      fracture(test::make_u_shape(), {ConvexCell{{below(Vec3(0, 2, 0), Vec3(0, -1, 0))}}});
  REQUIRE(f.size() == 2);
  CHECK(in_part_order(f));
  for (const Fragment& fragment : f) {
    CHECK(fragment.mass.volume == Approx(1.0).epsilon(1e-14));
    CHECK(tagged_area(fragment.mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-14));
    CHECK(closed_and_oriented(fragment.mesh));
  }
  // part_order_direction() has a positive x component: the left arm comes first.
  CHECK(f[0].mass.centroid.x() == Approx(0.5));
  CHECK(f[1].mass.centroid.x() == Approx(2.5));
}

TEST_CASE("cgal-cells: the eight octants of a box partition it", "[cgal-cells]") {
  // A box [0,2]x[0,1]x[0,3] from the unit cube, split at its centre.
  Mesh box = test::make_unit_cube();
  for (Vec3& p : box.vertices) p = p.cwiseProduct(Vec3(2, 1, 3));
  const Vec3 centre(1, 0.5, 1.5);
  std::vector<ConvexCell> cells;
  for (int i = 0; i < 8; ++i) {
    ConvexCell cell;
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = (i >> axis) & 1 ? -1.0 : 1.0;
      cell.planes.push_back(below(centre, normal));
    }
    cells.push_back(cell);
  }
  const std::vector<Fragment> f = fracture(box, cells);
  REQUIRE(f.size() == 8);
  double total = 0.0;
  double surface = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    CHECK(closed_and_oriented(f[i].mesh));
    CHECK(f[i].mass.volume == Approx(0.75).epsilon(1e-14));
    total += f[i].mass.volume;
    surface += tagged_area(f[i].mesh, FaceTag::surface);
    // Fragment i lies in octant i.
    for (int axis = 0; axis < 3; ++axis)
      CHECK((f[i].mass.centroid[axis] > centre[axis]) == static_cast<bool>((i >> axis) & 1));
  }
  CHECK(std::abs(total - 6.0) <= 1e-12 * 6.0);
  CHECK(surface == Approx(2 * (2 + 6 + 3)).epsilon(1e-14));
}

TEST_CASE("cgal-cells: cells that miss the solid give nothing", "[cgal-cells]") {
  const Mesh cube = test::make_unit_cube();
  // Far away; touching the face x = 1 from outside; empty (x <= 0.2 and x >= 0.4).
  const std::vector<ConvexCell> misses{
      ConvexCell{{below(Vec3(-5, 0, 0), Vec3(1, 0, 0))}},
      ConvexCell{{below(Vec3(1, 0, 0), Vec3(-1, 0, 0))}},
      ConvexCell{{below(Vec3(0.2, 0, 0), Vec3(1, 0, 0)), below(Vec3(0.4, 0, 0), Vec3(-1, 0, 0))}},
  };
  CHECK(fracture(cube, misses).empty());
  // A miss between two hits leaves the hits in order.
  std::vector<ConvexCell> mixed{ConvexCell{{below(Vec3(0.3, 0, 0), Vec3(1, 0, 0))}}, misses[0],
                                ConvexCell{{}}};
  const std::vector<Fragment> f = fracture(cube, mixed);
  REQUIRE(f.size() == 2);
  CHECK(f[0].mass.volume == Approx(0.3).epsilon(1e-14));
  CHECK(f[1].mass.volume == Approx(1.0).epsilon(1e-14));
  CHECK(tagged_area(f[1].mesh, FaceTag::cut) == 0.0);
}

TEST_CASE("cgal-cells: a solid's cut faces stay cut", "[cgal-cells]") {
  Mesh cube = test::make_unit_cube();
  for (FaceTag& tag : cube.tags) tag = FaceTag::cut;
  const std::vector<Fragment> f = fracture(cube, {ConvexCell{{below(Vec3(0.3, 0, 0), Vec3(1, 0, 0))}}});
  REQUIRE(f.size() == 1);
  CHECK(tagged_area(f[0].mesh, FaceTag::surface) == 0.0);
}

TEST_CASE("cgal-cells: the same input gives the same output", "[cgal-cells]") {
  // Bisector cells of a few sites in the U.
  const std::vector<Vec3> sites{{0.4, 0.3, 0.5}, {2.6, 0.6, 0.4}, {0.5, 2.5, 0.5}, {2.5, 2.2, 0.7}, {1.5, 0.5, 0.5}};
  std::vector<ConvexCell> cells(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (std::size_t j = 0; j < sites.size(); ++j)
      if (i != j) cells[i].planes.push_back(below(0.5 * (sites[i] + sites[j]), sites[j] - sites[i]));
  const Mesh u = test::make_u_shape();
  const std::vector<Fragment> a = fracture(u, cells);
  const std::vector<Fragment> b = fracture(u, cells);
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() >= sites.size());
  double total = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].mesh.vertices == b[i].mesh.vertices);
    CHECK(a[i].mesh.triangles == b[i].mesh.triangles);
    CHECK(a[i].mesh.tags == b[i].mesh.tags);
    CHECK(closed_and_oriented(a[i].mesh));
    total += a[i].mass.volume;
  }
  CHECK(std::abs(total - 7.0) <= 1e-12 * 7.0);
}

TEST_CASE("cgal-cells: bad planes are errors", "[cgal-cells]") {
  const CgalClipFracturer fracturer;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ConvexCell> not_finite{ConvexCell{{below(Vec3(nan, 0, 0), Vec3(1, 0, 0))}}};
  CHECK_FALSE(fracturer.fracture_by_cells(test::make_unit_cube(), not_finite).ok());
  const std::vector<ConvexCell> zero_normal{ConvexCell{}, ConvexCell{{below(Vec3(0.5, 0.5, 0.5), Vec3::Zero())}}};
  const Result<std::vector<Fragment>> result = fracturer.fracture_by_cells(test::make_unit_cube(), zero_normal);
  REQUIRE_FALSE(result.ok());
  CHECK(result.error().message.find("cell 1") != std::string::npos);
  CHECK_FALSE(fracturer.fracture_by_cells(Mesh{}, {}).ok());
}

}  // namespace shatter
