// The physics step of a frame: the planted slowdown is off in every build but the test-only one, and
// the step is one physics step.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "harness/pipeline/frame/planted_slowdown.h"
#include "harness/pipeline/physics/physics_world.h"

#include <catch2/catch.hpp>

namespace {

using namespace shatter;

}  // namespace

TEST_CASE("planted slowdown: off in this build, a frame's physics step moves a falling body by one step",
          "[pipeline][frame]") {
  REQUIRE(planted_slowdown_share() == 0.0);
  PhysicsSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  PhysicsWorld world(settings);
  Fragment cube;
  cube.mesh = make_box(Vec3(1, 1, 1), Vec3(0, 0, 10));
  cube.mass = mass_properties(cube.mesh);
  const int body = world.add_fragment(cube, 1000.0);
  const double z0 = world.position(body).z();
  step_physics(world);
  const double z1 = world.position(body).z();
  REQUIRE(world.step_count() == 1);
  REQUIRE(z1 < z0);
  REQUIRE(z0 - z1 == Approx(9.81 / 3600.0).epsilon(0.05));  // v = g dt, x = v dt after one semi-implicit step
}
