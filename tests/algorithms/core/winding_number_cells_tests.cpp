// WindingNumberCells against the plain sum over every triangle (winding_number), an independent answer.
#include "algorithms/core/winding_number_cells.h"

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/core/winding_number.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace shatter {
namespace {

/// Points drawn in the mesh's box (and a margin around it): each must round to the same winding
/// number as the brute-force sum; returns how many the cells answered.
int check_against_brute_force(const Mesh& mesh, int samples, std::uint64_t seed) {
  const WindingNumberCells cells(mesh);
  Aabb box = bounding_box(mesh);
  const Vec3 margin = 0.05 * (box.max - box.min);
  SplitMix64 rng(seed);
  int by_cells = 0;
  for (int i = 0; i < samples; ++i) {
    const Vec3 p = rng.point_in(box.min - margin, box.max + margin);
    const double brute = winding_number(mesh, p);
    INFO("point " << p.transpose() << ", brute force " << brute);
    REQUIRE(std::lround(cells(p)) == std::lround(brute));
    by_cells += cells.answered_by_cells(p) ? 1 : 0;
  }
  return by_cells;
}

}  // namespace

TEST_CASE("winding-number cells: the same integer as every triangle summed, on real meshes", "[winding]") {
  for (const std::string name : {"armadillo.off", "3torus.off", "cheese.off", "elephant.off"}) {
    const auto mesh = test::load_fixture_mesh(name);
    if (!mesh) return;
    INFO(name);
    const WindingNumberCells cells(*mesh);
    if (mesh->triangle_count() >= WindingNumberCells::kMinTriangles) CHECK(cells.cell_count() > 0);
    const int by_cells = check_against_brute_force(*mesh, 300, 7);
    if (cells.cell_count() > 0) CHECK(by_cells > 0);  // a lookup answers the points away from the surface
  }
}

TEST_CASE("winding-number cells: a sphere with a cavity counts 1 in the shell and 0 in the cavity", "[winding]") {
  Mesh outer = make_sphere(1.0, 64, 48);
  Mesh inner = make_sphere(0.5, 64, 48);
  for (Triangle& t : inner.triangles) std::swap(t[1], t[2]);
  Mesh both = outer;
  const auto offset = static_cast<std::int32_t>(both.vertices.size());
  for (const Vec3& v : inner.vertices) both.add_vertex(v);
  for (const Triangle& t : inner.triangles) both.add_triangle(t[0] + offset, t[1] + offset, t[2] + offset, FaceTag::surface);
  const WindingNumberCells cells(both);
  REQUIRE(cells.cell_count() > 0);
  CHECK(std::lround(cells({0.0, 0.0, 0.0})) == 0);
  CHECK(std::lround(cells({0.75, 0.0, 0.0})) == 1);
  CHECK(std::lround(cells({0.0, 0.0, 1.5})) == 0);
  check_against_brute_force(both, 300, 11);
}

TEST_CASE("winding-number cells: an open mesh gets no cells and the tree's exact value", "[winding]") {
  Mesh open = make_sphere(1.0, 64, 48);
  open.triangles.pop_back();
  open.tags.pop_back();
  const WindingNumberCells cells(open);
  CHECK(cells.cell_count() == 0);
  const WindingNumberQuery tree(open);
  for (const Vec3 p : {Vec3(0.1, 0.2, 0.3), Vec3(0.0, 0.0, -0.99), Vec3(0.5, 0.5, 0.5)})
    CHECK(cells(p) == tree(p));
}

}  // namespace shatter
