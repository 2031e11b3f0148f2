// plane-slice against the exact reference: the same cut schedule done by CGAL on an exact kernel must
// give the same fragments, volume by volume, to 1e-9 relative.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "tests/support/mesh_fixtures.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace shatter;

namespace {

void require_same_fragments(const std::vector<Fragment>& fast, const std::vector<Fragment>& exact,
                            const std::string& what) {
  INFO(what);
  REQUIRE(fast.size() == exact.size());
  for (std::size_t i = 0; i < fast.size(); ++i) {
    INFO("fragment " << i);
    const double scale = std::max(std::abs(exact[i].mass.volume), 1e-300);
    CHECK(std::abs(fast[i].mass.volume - exact[i].mass.volume) / scale <= 1e-9);
    CHECK((fast[i].mass.centroid - exact[i].mass.centroid).norm() <= 1e-7 * (1.0 + exact[i].mass.centroid.norm()));
  }
}

void compare_recursive(const Mesh& solid, int fragments, std::uint64_t seed, const std::string& what) {
  FractureParams params;
  params.fragments = fragments;
  params.seed = seed;
  auto fast = PlaneSliceFracturer().fracture(solid, params);
  auto exact = CgalClipFracturer().fracture(solid, params);
  REQUIRE(fast.ok());
  REQUIRE(exact.ok());
  require_same_fragments(*fast, *exact, what + " into " + std::to_string(fragments));
}

}  // namespace

TEST_CASE("plane-slice vs cgal-clip: explicit planes through vertices, edges and faces", "[plane-slice][cgal-clip]") {
  const Mesh cube = test::make_unit_cube();
  const std::vector<Plane> planes = {{Vec3(1, 0, 0), Vec3(1, 1, 1)},
                                     {Vec3(0, 0, 0), Vec3(1, -1, 0)},
                                     {Vec3(0, 0, 0.5), Vec3(0, 0, 1)},
                                     {Vec3(0, 0, 1), Vec3(0, 0, 1)}};
  auto fast = PlaneSliceFracturer().fracture_by_planes(cube, planes);
  auto exact = CgalClipFracturer().fracture_by_planes(cube, planes);
  REQUIRE((fast.ok() && exact.ok()));
  require_same_fragments(*fast, *exact, "cube");
}

TEST_CASE("plane-slice vs cgal-clip: recursive fracture of primitives", "[plane-slice][cgal-clip]") {
  compare_recursive(make_sphere(1.0, 24, 12), 5, 1, "sphere");
  compare_recursive(make_sphere(1.0, 24, 12), 25, 2, "sphere");
  compare_recursive(make_torus(2.0, 0.5, 32, 12), 25, 3, "torus");
  compare_recursive(test::make_u_shape(), 25, 4, "U shape");
}

TEST_CASE("plane-slice vs cgal-clip: real meshes", "[plane-slice][cgal-clip][real-meshes][slow]") {
  if (!test::have_meshes()) return;
  for (const char* name : {"elephant.off", "knot1.off"}) {
    const auto mesh = test::load_fixture_mesh(name);
    REQUIRE(mesh.has_value());
    compare_recursive(*mesh, 25, 1, name);
  }
}
