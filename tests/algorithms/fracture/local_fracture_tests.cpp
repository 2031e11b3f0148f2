// Runtime locality: an impact fractures only the fragments it reaches, by exact distance.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/local_fracture.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace shatter;

namespace {

/// A 3 x 3 x 3 m cube cut into 27 unit blocks by explicit planes.
std::vector<Fragment> blocks() {
  std::vector<Plane> planes;
  for (int axis = 0; axis < 3; ++axis)
    for (double at : {1.0, 2.0}) {
      Vec3 p = Vec3::Zero();
      p[axis] = at;
      planes.push_back({p, Vec3::Unit(axis)});
    }
  auto fragments = PlaneSliceFracturer().fracture_by_planes(make_box(Vec3(3, 3, 3), Vec3(1.5, 1.5, 1.5)), planes);
  REQUIRE(fragments.ok());
  REQUIRE(fragments->size() == 27);
  return std::move(*fragments);
}

Impact at(const Vec3& p, double radius) {
  Impact i;
  i.point = p;
  i.radius = radius;
  i.impulse = 100;
  return i;
}

}  // namespace

TEST_CASE("local fracture: the radius reaches faces, then edges, then corners", "[local-fracture]") {
  const auto frags = blocks();
  const Vec3 centre(1.5, 1.5, 1.5);
  // From the middle block's centre: face neighbours at 0.5, edge neighbours at 0.707, corners at 0.866.
  CHECK(fragments_near_impact(frags, at(centre, 0.1)).size() == 1);
  CHECK(fragments_near_impact(frags, at(centre, 0.6)).size() == 7);
  CHECK(fragments_near_impact(frags, at(centre, 0.75)).size() == 19);
  CHECK(fragments_near_impact(frags, at(centre, 0.9)).size() == 27);
}

TEST_CASE("local fracture: radius 0 picks the block holding the point, or the nearest", "[local-fracture]") {
  const auto frags = blocks();
  const auto inside = fragments_near_impact(frags, at(Vec3(2.5, 0.5, 0.5), 0.0));
  REQUIRE(inside.size() == 1);
  CHECK(frags[static_cast<std::size_t>(inside[0])].mass.centroid.isApprox(Vec3(2.5, 0.5, 0.5), 1e-12));
  const auto outside = fragments_near_impact(frags, at(Vec3(-1.0, 2.5, 2.5), 0.0));
  REQUIRE(outside.size() == 1);
  CHECK(frags[static_cast<std::size_t>(outside[0])].mass.centroid.isApprox(Vec3(0.5, 2.5, 2.5), 1e-12));
}

TEST_CASE("local fracture: only the hit block is fractured, and its volume is kept", "[local-fracture]") {
  const auto frags = blocks();
  FractureParams params;
  params.fragments = 8;
  params.seed = 3;
  auto local = fracture_near_impact(PlaneSliceFracturer(), frags, at(Vec3(0.5, 0.5, 0.5), 0.2), params);
  REQUIRE(local.ok());
  REQUIRE(local->hit.size() == 1);
  REQUIRE(local->pieces.size() == 1);
  CHECK(local->pieces[0].size() >= 8);
  double volume = 0;
  for (const Fragment& f : local->pieces[0]) volume += f.mass.volume;
  CHECK(volume == Approx(frags[static_cast<std::size_t>(local->hit[0])].mass.volume).epsilon(1e-12));
  // An impact far from everything with a small radius breaks nothing.
  auto miss = fracture_near_impact(PlaneSliceFracturer(), frags, at(Vec3(10, 10, 10), 0.5), params);
  REQUIRE(miss.ok());
  CHECK(miss->hit.empty());
}
