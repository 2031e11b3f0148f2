// voronoi against its exact reference: the same bisector planes replayed as convex cells by CGAL
// (corefinement with each exact cell polytope) give the same fragments, volume by volume, to 1e-9.

#include "algorithms/core/primitives.h"
#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_cells.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"
#include "tests/support/mesh_fixtures.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

using namespace shatter;

namespace {

void compare_with_replay(const Mesh& solid, int sites_wanted, std::uint64_t seed, const std::string& what) {
  INFO(what << ", " << sites_wanted << " sites");
  FractureParams params;
  params.fragments = sites_wanted;
  params.seed = seed;
  auto sites = sample_sites(solid, params);
  REQUIRE(sites.ok());
  std::vector<ConvexCell> cells(sites->size());
  for (int i = 0; i < static_cast<int>(sites->size()); ++i)
    for (int j = 0; j < static_cast<int>(sites->size()); ++j)
      if (i != j) cells[static_cast<std::size_t>(i)].planes.push_back(bisector_plane(*sites, i, j));
  auto fast = VoronoiFracturer().fracture_with_sites(solid, *sites);
  auto exact = CgalClipFracturer().fracture_by_cells(solid, cells);
  REQUIRE(fast.ok());
  REQUIRE(exact.ok());
  REQUIRE(fast->size() == exact->size());
  // The parts of one cell may come in another order: pair each fragment with the nearest centroid.
  std::vector<bool> used(exact->size(), false);
  for (const Fragment& f : *fast) {
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < exact->size(); ++k) {
      const double d = (f.mass.centroid - (*exact)[k].mass.centroid).norm();
      if (!used[k] && d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
    used[best] = true;
    const double v = (*exact)[best].mass.volume;
    CHECK(std::abs(f.mass.volume - v) <= 1e-9 * v);
  }
}

}  // namespace

TEST_CASE("voronoi vs cgal-clip: primitives", "[voronoi][cgal-clip]") {
  compare_with_replay(make_sphere(1.0, 24, 12), 10, 1, "sphere");
  compare_with_replay(test::make_u_shape(), 8, 2, "U shape");
  compare_with_replay(make_torus(2.0, 0.5, 32, 12), 12, 3, "torus");
}

TEST_CASE("voronoi vs cgal-clip: elephant into 25 cells", "[voronoi][cgal-clip][real-meshes][slow]") {
  if (!test::have_meshes()) return;
  const auto elephant = test::load_fixture_mesh("elephant.off");
  REQUIRE(elephant.has_value());
  compare_with_replay(*elephant, 25, 1, "elephant");
}
