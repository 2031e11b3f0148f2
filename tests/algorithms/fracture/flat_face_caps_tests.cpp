// Caps across flat faces: where a cut crosses a flat face split into several triangles, the outline
// has three points on one straight line, rounded apart. A cap fanned from one of them made a sliver
// lying in the face and folded onto the face's own triangles, a self-intersection by the acceptance
// rule (solid_check.h), so fracturing that fragment again was refused. Seen on the tower and wall
// cases (voronoi at runtime), whose solids are boxes and prisms with flat faces.

#include "algorithms/core/primitives.h"
#include "algorithms/core/solid_check.h"
#include "algorithms/fracture/plane_slice/convex_cap.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace shatter;

TEST_CASE("flat-face caps: a convex loop with a straight corner is not fanned", "[convex-cap][acceptance]") {
  // A triangle with a point on one side, off the line by about one rounding step.
  const std::vector<Vec2> points = {{0, 0}, {0.5, -1e-17}, {1, 0}, {0, 1}};
  const std::vector<CapEdge> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<Triangle> triangles;
  CHECK_FALSE(fan_convex_cap(points, edges, triangles));
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  CHECK(fan_convex_cap(square, edges, triangles));
}

TEST_CASE("flat-face caps: every voronoi fragment of a box passes the acceptance rule", "[voronoi][acceptance]") {
  const Mesh tower = make_box(Vec3(2, 2, 10), Vec3(0, 0, 5));
  const VoronoiFracturer voronoi;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    FractureParams params;
    params.fragments = 25;
    params.seed = seed;
    auto fragments = voronoi.fracture(tower, params);
    REQUIRE(fragments.ok());
    for (std::size_t i = 0; i < fragments->size(); ++i) {
      INFO("seed " << seed << ", fragment " << i);
      const Status s = check_solid((*fragments)[i].mesh, "voronoi fragment", nullptr);
      CHECK(s.ok());
      if (!s) WARN(s.error().message);
    }
  }
}

TEST_CASE("flat-face caps: plane-slice fragments of a box fracture again with voronoi", "[voronoi][plane-slice][acceptance]") {
  const Mesh tower = make_box(Vec3(2, 2, 10), Vec3(0, 0, 5));
  const VoronoiFracturer voronoi;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    FractureParams pre;
    pre.fragments = 60;
    pre.seed = seed;
    auto fragments = PlaneSliceFracturer().fracture(tower, pre);
    REQUIRE(fragments.ok());
    for (std::size_t i = 0; i < fragments->size(); i += 5) {
      INFO("seed " << seed << ", fragment " << i);
      FractureParams runtime;
      runtime.fragments = 15;
      runtime.seed = seed * 100 + i;
      auto pieces = voronoi.fracture((*fragments)[i].mesh, runtime);
      REQUIRE(pieces.ok());
      for (const Fragment& p : *pieces) CHECK(check_solid(p.mesh, "runtime piece", nullptr).ok());
    }
  }
}
