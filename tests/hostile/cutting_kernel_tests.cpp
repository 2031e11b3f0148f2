// The cutting kernel plugins are pointed to (PlaneSliceFracturer::fracture_by_planes) on the planes
// that broke it: a cut within an ulp of a row of vertices followed by any second cut of the same
// piece, axis-aligned slabs of an axis-aligned mesh at and beside its vertex rows, a plane repeated,
// a plane that misses. Every cut is made or counted as a miss; the counts and volumes are known in
// closed form.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace shatter;

namespace {

Plane axis_plane(int axis, double at) {
  Plane p;
  p.point = Vec3(0.5, 0.5, 0.5);
  p.point[axis] = at;
  p.normal = Vec3::Unit(axis);
  return p;
}

/// Cuts with every cut required, and checks closed pieces and the total volume.
std::vector<Fragment> cut_all(const Mesh& solid, const std::vector<Plane>& planes, CutTally& tally) {
  Result<std::vector<Fragment>> pieces = PlaneSliceFracturer().fracture_by_planes(
      solid, planes, kMaxFragments, nullptr, PlaneSliceFracturer::FailedCut::refuse, &tally);
  if (!pieces) FAIL(pieces.error().message);
  CHECK(tally.failed == 0);
  double sum = 0.0;
  for (const Fragment& f : *pieces) {
    CHECK(is_closed_and_oriented(f.mesh));
    sum += f.mass.volume;
  }
  CHECK(std::abs(sum - signed_volume(solid)) <= 1e-12 * signed_volume(solid));
  return std::move(*pieces);
}

std::vector<double> sorted_volumes(const std::vector<Fragment>& pieces) {
  std::vector<double> v;
  for (const Fragment& f : pieces) v.push_back(f.mass.volume);
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("cutting kernel: after a cut 2.2e-16 from a row of vertices, a second cut at any offset is made",
          "[hostile][plane-slice]") {
  const Mesh cube = test::grid_cube(8);  // vertex rows at every k / 8
  const Plane first = axis_plane(0, 0.25 + 2.2e-16);
  for (const double offset : {1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3}) {
    INFO("second cut at 0.25 + " << offset);
    CutTally tally;
    const std::vector<Fragment> pieces = cut_all(cube, {first, axis_plane(0, 0.25 + offset)}, tally);
    REQUIRE(pieces.size() == 3);
    CHECK(tally.cuts == 2);
    // The slab between the cuts, and the two sides, to the input's rounding.
    const std::vector<double> v = sorted_volumes(pieces);
    CHECK(std::abs(v[0] - offset) <= 1e-15);
    CHECK(std::abs(v[1] - 0.25) <= 1e-14);
    CHECK(std::abs(v[2] - (0.75 - offset)) <= 1e-14);
  }
}

TEST_CASE("cutting kernel: 24 axis-aligned slabs at and beside the vertex rows of a grid-aligned box make 729 pieces",
          "[hostile][plane-slice]") {
  const Mesh cube = test::grid_cube(8);
  const double beside[] = {0.0, 2.2e-16, -2.2e-16, 4.4e-16, -1e-15, 1e-15, 0.0};
  std::vector<Plane> planes;
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 1; k <= 7; ++k) planes.push_back(axis_plane(axis, k / 8.0 + beside[k - 1]));
    planes.push_back(axis_plane(axis, 0.5 + 1e-12));  // a slab 1e-12 thick beside the row at 0.5
  }
  REQUIRE(planes.size() == 24);
  CutTally tally;
  const std::vector<Fragment> pieces = cut_all(cube, planes, tally);
  // Eight distinct planes across each axis: 9 x 9 x 9 boxes.
  CHECK(pieces.size() == 729);
  // The thinnest are the 1e-12 slabs' corners, the largest the 1/8-cubes.
  const std::vector<double> v = sorted_volumes(pieces);
  CHECK(std::abs(v.front() - 1e-36) <= 1e-38);
  CHECK(std::abs(v.back() - 1.0 / 512.0) <= 1e-14);
}

TEST_CASE("cutting kernel: a plane that misses, or repeats an earlier cut, is a counted no-op",
          "[hostile][plane-slice]") {
  const Mesh cube = test::grid_cube(4);
  CutTally missed;
  CHECK(cut_all(cube, {axis_plane(2, 2.0)}, missed).size() == 1);
  CHECK(missed.cuts == 0);
  CHECK(missed.misses == 1);
  // The second plane lies on both pieces' cap (their rounded points): a miss for each, not slivers.
  const Plane diagonal{Vec3(0.3, 0.0, 0.5), Vec3(1.0, -0.7, 0.2)};
  CutTally repeated;
  const std::vector<Fragment> pieces = cut_all(cube, {diagonal, diagonal}, repeated);
  CHECK(pieces.size() == 2);
  CHECK(repeated.cuts == 1);
  CHECK(repeated.misses == 2);
}
