// Every mesh of CGAL's data set: a closed one fractures into 5, 25 and 100 closed fragments with the
// volume conserved and the input partitioned, deterministically; an open or broken one is refused with
// a one-line reason.

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/cases/load_solid.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <vector>

using namespace shatter;

namespace {

std::vector<std::filesystem::path> all_meshes() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(test::mesh_dir()))
    if (e.path().extension() == ".off") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("plane-slice: every closed mesh of the CGAL data set fractures cleanly", "[plane-slice][real-meshes][slow]") {
  if (!test::have_meshes()) return;
  int closed = 0;
  int refused = 0;
  for (const auto& path : all_meshes()) {
    INFO(path.filename().string());
    Result<Solid> solid = load_solid(path);
    if (!solid) {
      ++refused;
      const std::string& message = solid.error().message;
      CHECK(message.find('\n') == std::string::npos);
      CHECK_THAT(message, Catch::Contains(path.filename().string()));
      if (path.filename().string().find("holes") != std::string::npos || path.filename() == "mushroom.off")
        CHECK_THAT(message, Catch::Contains("not closed"));
      continue;
    }
    ++closed;
    for (int n : {5, 25, 100}) {
      INFO(n << " fragments");
      FractureParams params;
      params.fragments = n;
      params.seed = 11;
      auto fragments = PlaneSliceFracturer().fracture(solid->mesh, params);
      REQUIRE(fragments.ok());
      const FractureMetrics m = fracture_metrics(solid->mesh, solid->mass, *fragments, n,
                                                 FractureMetricsOptions{.partition_samples = 500, .seed = 5});
      CHECK(m.all_closed);
      CHECK(m.volume_error <= 1e-9);
      CHECK(m.partition_error == 0.0);
      CHECK(m.fragment_count >= std::min(n, 1));
      if (n == 25) {
        auto again = PlaneSliceFracturer().fracture(solid->mesh, params);
        REQUIRE(again.ok());
        REQUIRE(again->size() == fragments->size());
        for (std::size_t i = 0; i < again->size(); ++i)
          CHECK((*again)[i].mesh.vertices == (*fragments)[i].mesh.vertices);
      }
    }
  }
  WARN("CGAL data set: " << closed << " closed meshes fractured, " << refused << " refused");
  CHECK(closed > 50);
}
