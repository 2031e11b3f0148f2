// voronoi: the shared invariants (closed, volume, partition) on primitives and real meshes, the one
// cut known in closed form (two sites: the bisector plane), determinism, the impact clustering, and
// bad parameters.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/core/winding_number.h"
#include "algorithms/fracture/voronoi/point_in_mesh.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/mesh_fixtures.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace shatter;

namespace {

std::vector<Fragment> voronoi(const Mesh& solid, int fragments, std::uint64_t seed,
                              std::optional<Impact> impact = std::nullopt) {
  FractureParams params;
  params.fragments = fragments;
  params.seed = seed;
  params.impact = impact;
  auto result = VoronoiFracturer().fracture(solid, params);
  REQUIRE(result.ok());
  return std::move(*result);
}

void require_valid_fracture(const Mesh& solid, const std::vector<Fragment>& fragments, int requested) {
  REQUIRE(static_cast<int>(fragments.size()) >= requested);  // every site's cell meets the solid
  for (const Fragment& f : fragments) {
    REQUIRE(is_closed_and_oriented(f.mesh));
    REQUIRE(all_finite(f.mesh));
    REQUIRE(f.mass.volume > 0);
  }
  const FractureMetrics m = fracture_metrics(solid, mass_properties(solid), fragments, requested,
                                             FractureMetricsOptions{.partition_samples = 1000, .seed = 9});
  CHECK(m.all_closed);
  CHECK(m.volume_error <= 1e-9);
  CHECK(m.partition_error == 0.0);
  CHECK(m.area_error <= 1e-9);
}

}  // namespace

TEST_CASE("voronoi: primitives into 5, 25 and 100 fragments stay closed and partition", "[voronoi]") {
  const std::vector<Mesh> solids = {make_sphere(1.0, 32, 16), make_box(Vec3(4, 1, 0.5)),
                                    make_torus(2.0, 0.5, 48, 24), test::make_u_shape()};
  for (std::size_t s = 0; s < solids.size(); ++s) {
    for (int n : {5, 25, 100}) {
      INFO("solid " << s << ", " << n << " fragments");
      require_valid_fracture(solids[s], voronoi(solids[s], n, 21), n);
    }
  }
}

TEST_CASE("voronoi: real meshes into 5, 25 and 100 fragments stay closed and partition", "[voronoi][real-meshes]") {
  if (!test::have_meshes()) return;
  for (const char* name : {"elephant.off", "knot1.off", "homer.off"}) {
    const auto solid = test::load_fixture_mesh(name);
    REQUIRE(solid.has_value());
    for (int n : {5, 25, 100}) {
      INFO(name << ", " << n << " fragments");
      require_valid_fracture(*solid, voronoi(*solid, n, 5), n);
    }
  }
}

TEST_CASE("voronoi: two sites in a box cut it along their bisector plane", "[voronoi]") {
  // The box [0,2] x [0,1] x [0,1].
  const Mesh box = make_box(Vec3(2, 1, 1), Vec3(1, 0.5, 0.5));
  SECTION("axis-aligned pair: the plane x = 0.75") {
    const std::vector<Vec3> sites = {Vec3(0.25, 0.5, 0.5), Vec3(1.25, 0.5, 0.5)};
    auto fragments = VoronoiFracturer().fracture_with_sites(box, sites);
    REQUIRE(fragments.ok());
    REQUIRE(fragments->size() == 2);
    CHECK((*fragments)[0].mass.volume == Approx(0.75).epsilon(1e-12));
    CHECK((*fragments)[1].mass.volume == Approx(1.25).epsilon(1e-12));
    for (const Fragment& f : *fragments) CHECK(tagged_area(f.mesh, FaceTag::cut) == Approx(1.0).epsilon(1e-12));
  }
  SECTION("oblique pair: the plane x + y = 1.5 through the box") {
    // Bisector of (0.5, 0.5, 0.5) and (1, 1, 0.5): through (0.75, 0.75, 0.5), normal (1, 1, 0).
    const std::vector<Vec3> sites = {Vec3(0.5, 0.5, 0.5), Vec3(1.0, 1.0, 0.5)};
    auto fragments = VoronoiFracturer().fracture_with_sites(box, sites);
    REQUIRE(fragments.ok());
    REQUIRE(fragments->size() == 2);
    // Beyond the plane, each y in [0, 1] has x in [1.5 - y, 2]: area 0.5 + 0.5 = 1, so volume 1 on
    // each side; the cut is the segment (1.5, 0)-(0.5, 1) of length sqrt(2) times the height 1.
    CHECK((*fragments)[0].mass.volume == Approx(1.0).epsilon(1e-12));
    CHECK((*fragments)[1].mass.volume == Approx(1.0).epsilon(1e-12));
    for (const Fragment& f : *fragments)
      CHECK(tagged_area(f.mesh, FaceTag::cut) == Approx(std::sqrt(2.0)).epsilon(1e-12));
  }
}

TEST_CASE("voronoi: a site whose cell misses the solid gives no fragment", "[voronoi]") {
  const Mesh cube = test::make_unit_cube();
  const std::vector<Vec3> sites = {Vec3(0.5, 0.5, 0.5), Vec3(5, 5, 5)};
  auto fragments = VoronoiFracturer().fracture_with_sites(cube, sites);
  REQUIRE(fragments.ok());
  REQUIRE(fragments->size() == 1);
  CHECK((*fragments)[0].mass.volume == Approx(1.0).epsilon(1e-14));
  CHECK(tagged_area((*fragments)[0].mesh, FaceTag::cut) == 0.0);
}

TEST_CASE("voronoi: the same seed gives the same fragments, another seed others", "[voronoi]") {
  const Mesh torus = make_torus(2.0, 0.5, 32, 16);
  const auto a = voronoi(torus, 30, 42);
  const auto b = voronoi(torus, 30, 42);
  const auto c = voronoi(torus, 30, 43);
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].mesh.vertices == b[i].mesh.vertices);
    CHECK(a[i].mesh.triangles == b[i].mesh.triangles);
    CHECK(a[i].mesh.tags == b[i].mesh.tags);
  }
  bool differs = a.size() != c.size();
  for (std::size_t i = 0; !differs && i < a.size(); ++i) differs = a[i].mass.volume != c[i].mass.volume;
  CHECK(differs);
}

TEST_CASE("voronoi: fragments are small near the impact and large far from it", "[voronoi]") {
  const Mesh slab = make_box(Vec3(8, 4, 1));
  Impact impact;
  impact.point = Vec3(-3.5, 0, 0.5);  // on the top face, near one end
  impact.radius = 1.0;
  const auto fragments = voronoi(slab, 60, 3, impact);
  require_valid_fracture(slab, fragments, 60);
  double near_sum = 0, far_sum = 0;
  int near_count = 0, far_count = 0;
  for (const Fragment& f : fragments) {
    const double d = (f.mass.centroid - impact.point).norm();
    if (d <= impact.radius) near_sum += f.mass.volume, ++near_count;
    if (d >= 2 * impact.radius) far_sum += f.mass.volume, ++far_count;
  }
  REQUIRE(near_count > 0);
  REQUIRE(far_count > 0);
  CHECK(near_sum / near_count * 10 < far_sum / far_count);
}

TEST_CASE("voronoi: the inside test agrees with the winding number", "[voronoi]") {
  const Mesh torus = make_torus(2.0, 0.5, 24, 12);
  const PointInMesh inside(torus);
  SplitMix64 rng(4);
  int decided = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 q = rng.point_in(Vec3(-3, -3, -1), Vec3(3, 3, 1));
    const InsideAnswer a = inside(q);
    if (a == InsideAnswer::undecided) continue;
    ++decided;
    CHECK((a == InsideAnswer::inside) == (winding_number(torus, q) > 0.5));
  }
  CHECK(decided > 1990);
}

TEST_CASE("voronoi: bad parameters are errors, not crashes", "[voronoi]") {
  const Mesh cube = test::make_unit_cube();
  FractureParams params;
  params.fragments = 0;
  CHECK_FALSE(VoronoiFracturer().fracture(cube, params).ok());
  params.fragments = 4;
  params.impact = Impact{};
  params.impact->radius = -1.0;
  CHECK_FALSE(VoronoiFracturer().fracture(cube, params).ok());
  params.impact->radius = std::nan("");
  CHECK_FALSE(VoronoiFracturer().fracture(cube, params).ok());
  params.impact.reset();
  VoronoiSettings settings;
  settings.sites.impact_share = 1.5;
  CHECK_FALSE(VoronoiFracturer(settings).fracture(cube, params).ok());
  settings = {};
  settings.leaf_cells = 0;
  CHECK_FALSE(VoronoiFracturer(settings).fracture(cube, params).ok());
  const std::vector<Vec3> twice = {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5)};
  const auto same = VoronoiFracturer().fracture_with_sites(cube, twice);
  REQUIRE_FALSE(same.ok());
  CHECK_THAT(same.error().message, Catch::Contains("coincide"));
  const std::vector<Vec3> nan_site = {Vec3(std::nan(""), 0, 0)};
  CHECK_FALSE(VoronoiFracturer().fracture_with_sites(cube, nan_site).ok());
  CHECK_FALSE(VoronoiFracturer().fracture_with_sites(cube, std::vector<Vec3>{}).ok());
}

TEST_CASE("voronoi: a sliver that fills little of its box still fractures, with the sites it could place",
          "[voronoi]") {
  // A 1 x 1 x 1e-5 plate turned 45 degrees about x and then y fills about 1e-5 of its bounding box:
  // rejection sampling finds few or no sites. The fracture must not fail (a runtime fracture of a
  // sliver fragment would otherwise fail a whole frame); it may return fewer fragments than asked.
  Mesh plate = make_box(Vec3(1.0, 1.0, 1e-5), Vec3::Zero());
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()) * Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()))
                                   .toRotationMatrix();
  for (Vec3& v : plate.vertices) v = turn * v;
  const MassProperties whole = mass_properties(plate);
  FractureParams params;
  params.fragments = 5;
  params.seed = 3;
  auto fragments = VoronoiFracturer().fracture(plate, params);
  REQUIRE(fragments);
  REQUIRE(!fragments->empty());
  const FractureMetrics m = fracture_metrics(plate, whole, *fragments, 5);
  CHECK(m.all_closed);
  CHECK(m.volume_error < 1e-9);
}
