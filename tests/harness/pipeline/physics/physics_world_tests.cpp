// PhysicsWorld: the Bullet wrapper hands Bullet the exact mass properties of the fragment meshes and
// integrates them as documented (semi-implicit Euler, fixed 1/60 s steps).

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "harness/pipeline/physics/physics_world.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using shatter::Fragment;
using shatter::PhysicsSettings;
using shatter::PhysicsWorld;
using shatter::Vec3;

Fragment box_fragment(const Vec3& size, const Vec3& center) {
  Fragment f;
  f.mesh = shatter::make_box(size, center);
  f.mass = shatter::mass_properties(f.mesh);
  return f;
}

PhysicsSettings no_gravity() {
  PhysicsSettings s;
  s.gravity = Vec3::Zero();
  return s;
}

}  // namespace

TEST_CASE("physics-world: free fall follows the discrete semi-implicit Euler formula", "[physics]") {
  PhysicsWorld world;  // default gravity, no ground
  const double z0 = 10.0;
  const int id = world.add_fragment(box_fragment(Vec3(1, 1, 1), Vec3(0, 0, z0)), 1000.0, false);
  const double g = 9.81;
  const double dt = 1.0 / 60.0;
  const int n = 30;
  for (int i = 0; i < n; ++i) world.step();
  // v_n = -g dt n, z_n = z0 - g dt^2 n(n+1)/2 (velocity first, then position).
  const double drop = g * dt * dt * n * (n + 1) / 2.0;
  const Vec3 p = world.position(id);
  CHECK(std::abs((z0 - p.z()) - drop) <= 1e-4 * drop);
  CHECK(std::abs(p.x()) < 1e-9);
  CHECK(std::abs(p.y()) < 1e-9);
  CHECK(world.linear_velocity(id).z() == Approx(-g * dt * n).epsilon(1e-5));
  CHECK(world.step_count() == n);
}

TEST_CASE("physics-world: a box resting on the ground stays at rest", "[physics]") {
  PhysicsSettings s;
  s.ground = true;
  s.ground_z = 0.0;
  s.allow_sleeping = false;  // measure the solver, not the sleeping
  PhysicsWorld world(s);
  // Hulls are inset by the margin: the mesh itself touches the ground.
  const int id = world.add_fragment(box_fragment(Vec3(1, 1, 1), Vec3(0, 0, 0.5)),
                                    1000.0, false);
  for (int i = 0; i < 120; ++i) world.step();
  CHECK(world.linear_velocity(id).norm() < 1e-2);
  CHECK(world.angular_velocity(id).norm() < 1e-2);
  CHECK(world.position(id).z() == Approx(0.5).margin(0.05));
  CHECK((world.rotation(id) - Eigen::Matrix3d::Identity()).norm() < 1e-3);
}

TEST_CASE("physics-world: a sphere with a reduced hull lands and rests on the ground", "[physics]") {
  PhysicsSettings s;
  s.ground = true;
  s.max_hull_vertices = 24;
  PhysicsWorld world(s);
  Fragment sphere;
  sphere.mesh = shatter::make_sphere(0.5, 32, 16, Vec3(0, 0, 1.0));
  sphere.mass = shatter::mass_properties(sphere.mesh);
  const int id = world.add_fragment(sphere, 1000.0, false);
  for (int i = 0; i < 240; ++i) world.step();
  CHECK(world.linear_velocity(id).norm() < 5e-2);
  CHECK(world.position(id).z() == Approx(0.5).margin(0.1));
}

TEST_CASE("physics-world: mass and principal inertia are exact for an asymmetric box", "[physics]") {
  PhysicsWorld world(no_gravity());
  const double density = 2500.0;
  const Vec3 center(1.0, -2.0, 3.0);
  const int id = world.add_fragment(box_fragment(Vec3(1, 2, 3), center), density, false);
  const double m = density * 6.0;
  CHECK(world.mass(id) == Approx(m).epsilon(1e-6));
  // Ascending: about z (1^2 + 2^2), about y (1^2 + 3^2), about x (2^2 + 3^2), times m / 12.
  const Vec3 moments = world.principal_inertia(id);
  CHECK(moments.x() == Approx(m / 12.0 * 5.0).epsilon(1e-6));
  CHECK(moments.y() == Approx(m / 12.0 * 10.0).epsilon(1e-6));
  CHECK(moments.z() == Approx(m / 12.0 * 13.0).epsilon(1e-6));
  // The principal frame stays internal: position is the centroid, rotation the identity.
  CHECK((world.position(id) - center).norm() < 1e-6);
  CHECK((world.rotation(id) - Eigen::Matrix3d::Identity()).norm() < 1e-6);
}

TEST_CASE("physics-world: an impulse gives velocity J/m and the matching spin", "[physics]") {
  PhysicsWorld world(no_gravity());
  const double density = 2.0;
  const Vec3 center(0.0, 0.0, 5.0);
  const int id = world.add_fragment(box_fragment(Vec3(1, 2, 3), center), density, false);
  const double m = density * 6.0;

  SECTION("at the centroid: pure translation") {
    const Vec3 j(3.0, -1.5, 6.0);
    world.apply_impulse(id, j, center);
    world.step();
    CHECK((world.linear_velocity(id) - j / m).norm() < 1e-5 * (j / m).norm());
    CHECK(world.angular_velocity(id).norm() < 1e-9);
    CHECK((world.position(id) - (center + j / m / 60.0)).norm() < 1e-5);
  }
  SECTION("off the centroid: spin about a principal axis, w = I^-1 (r x J)") {
    const Vec3 j(0.0, 0.0, 2.0);
    const Vec3 r(0.5, 0.0, 0.0);
    world.apply_impulse(id, j, center + r);
    world.step();
    const double i_yy = m / 12.0 * (1.0 + 9.0);
    CHECK((world.linear_velocity(id) - j / m).norm() < 1e-5);
    CHECK(world.angular_velocity(id).y() == Approx(r.cross(j).y() / i_yy).epsilon(1e-4));
    CHECK(std::abs(world.angular_velocity(id).x()) < 1e-6);
    CHECK(std::abs(world.angular_velocity(id).z()) < 1e-6);
  }
}

TEST_CASE("physics-world: static bodies do not move", "[physics]") {
  PhysicsWorld world;
  const Vec3 center(0.0, 0.0, 5.0);
  const int id = world.add_fragment(box_fragment(Vec3(1, 1, 1), center), 1000.0, true);
  world.apply_impulse(id, Vec3(100, 0, 0), center);
  for (int i = 0; i < 60; ++i) world.step();
  CHECK((world.position(id) - center).norm() < 1e-9);
  CHECK(world.linear_velocity(id).norm() == 0.0);
  CHECK(world.mass(id) == 0.0);
}

TEST_CASE("physics-world: removing a body reduces the count and retires the id", "[physics]") {
  PhysicsWorld world;
  const int a = world.add_fragment(box_fragment(Vec3(1, 1, 1), Vec3(0, 0, 0)), 1.0, false);
  const int b = world.add_fragment(box_fragment(Vec3(1, 1, 1), Vec3(3, 0, 0)), 1.0, false);
  CHECK(world.body_count() == 2);
  world.remove(a);
  CHECK(world.body_count() == 1);
  CHECK_FALSE(world.contains(a));
  CHECK(world.contains(b));
  const int c = world.add_fragment(box_fragment(Vec3(1, 1, 1), Vec3(6, 0, 0)), 1.0, false);
  CHECK(c != a);
  world.step();
  CHECK(world.body_count() == 2);
}

TEST_CASE("physics-world: a cluster of two cubes has the mass properties of a 2 x 1 x 1 box", "[physics]") {
  PhysicsWorld world(no_gravity());
  const std::vector<Fragment> cubes = {box_fragment(Vec3(1, 1, 1), Vec3(-0.5, 0, 2)),
                                       box_fragment(Vec3(1, 1, 1), Vec3(0.5, 0, 2))};
  const double density = 10.0;
  const int id = world.add_cluster(cubes, density, false);
  const double m = density * 2.0;
  CHECK(world.mass(id) == Approx(m).epsilon(1e-6));
  const Vec3 moments = world.principal_inertia(id);
  CHECK(moments.x() == Approx(m / 12.0 * 2.0).epsilon(1e-6));
  CHECK(moments.y() == Approx(m / 12.0 * 5.0).epsilon(1e-6));
  CHECK(moments.z() == Approx(m / 12.0 * 5.0).epsilon(1e-6));
  CHECK((world.position(id) - Vec3(0, 0, 2)).norm() < 1e-6);
  world.apply_impulse(id, Vec3(0, m, 0), Vec3(0, 0, 2));
  world.step();
  CHECK((world.linear_velocity(id) - Vec3(0, 1, 0)).norm() < 1e-5);
}

TEST_CASE("physics-world: bad settings are an error naming the field", "[physics]") {
  PhysicsSettings s;
  s.fixed_step = 0.0;
  const auto world = PhysicsWorld::create(s);
  REQUIRE_FALSE(world.ok());
  CHECK(world.error().message.find("physics.fixed_step") != std::string::npos);
  s = PhysicsSettings{};
  s.restitution = 2.0;
  CHECK_FALSE(PhysicsWorld::create(s).ok());
  CHECK(PhysicsWorld::create(PhysicsSettings{}).ok());
}

TEST_CASE("physics-world: fragments that share a face start touching, not pushed apart", "[physics]") {
  // Hulls are inset by the collision margin, so a stack of blocks that share faces (as fragments of one
  // fracture do) is at rest from the first step: nothing is ejected by resolving a margin overlap.
  PhysicsSettings s;
  s.ground = true;
  s.collision_margin = 0.02;  // large, so a missing inset would show as centimetres of motion
  PhysicsWorld world(s);
  const int base = world.add_fragment(box_fragment(Vec3(1, 1, 1), Vec3(0, 0, 0.5)), 2400.0, true);
  const int left = world.add_fragment(box_fragment(Vec3(0.5, 1, 1), Vec3(-0.25, 0, 1.5)), 2400.0, false);
  const int right = world.add_fragment(box_fragment(Vec3(0.5, 1, 1), Vec3(0.25, 0, 1.5)), 2400.0, false);
  for (int i = 0; i < 60; ++i) world.step();
  REQUIRE(world.contains(base));
  for (const int id : {left, right}) {
    const Vec3 start = id == left ? Vec3(-0.25, 0, 1.5) : Vec3(0.25, 0, 1.5);
    CHECK((world.position(id) - start).norm() < 0.005);
    CHECK(world.linear_velocity(id).norm() < 0.05);
  }
}

namespace {

/// A block of n x n x n cubes of side 0.2 m, each touching its neighbours, on the ground: the boxes of
/// every cube and its 26 neighbours overlap, ((3n - 2)^3 - n^3) / 2 pairs (5068 for n = 8).
std::vector<Fragment> cube_block(int n) {
  std::vector<Fragment> cubes;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) cubes.push_back(box_fragment(Vec3(0.2, 0.2, 0.2), Vec3(0.2 * i, 0.2 * j, 0.1 + 0.2 * k)));
  return cubes;
}

}  // namespace

TEST_CASE("physics-world: the contact pool's size changes no trajectory", "[physics]") {
  // The pool sizes the manifolds, the broadphase's pair cache and the solver's constraint arrays
  // (presized_pools.h): with 1024 all three grow inside the steps, with 16384 none does.
  const std::vector<Fragment> cubes = cube_block(8);
  std::vector<std::vector<Vec3>> paths(2);
  std::vector<int> pairs(2);
  std::vector<int> contact_points(2);
  for (int run = 0; run < 2; ++run) {
    PhysicsSettings s;
    s.ground = true;
    s.contact_pool_size = run == 0 ? 1024 : 16384;  // the first allocates what is beyond 1024 in the steps
    PhysicsWorld world(s);
    std::vector<int> ids;
    for (const Fragment& f : cubes) ids.push_back(world.add_fragment(f, 1000.0));
    // Knock the block's top corner so that the pile moves.
    world.apply_impulse(ids.back(), Vec3(-40.0, -25.0, 10.0), cubes.back().mass.centroid + Vec3(0.1, 0.1, 0.1));
    for (int step = 0; step < 30; ++step) {
      world.step();
      for (const int id : ids) paths[static_cast<std::size_t>(run)].push_back(world.position(id));
      int points = 0;
      for (const shatter::TouchingPair& t : world.touching_pairs()) points += t.points;
      contact_points[static_cast<std::size_t>(run)] = std::max(contact_points[static_cast<std::size_t>(run)], points);
    }
    pairs[static_cast<std::size_t>(run)] = world.overlapping_pairs();
  }
  CHECK(pairs[0] > 4096);  // beyond the small pool, and beyond Bullet's default
  CHECK(pairs[0] <= 16384);
  CHECK(contact_points[0] > 1024);  // the solver's contact and friction arrays outgrew the small pool
  CHECK(contact_points[0] <= 16384);
  CHECK(contact_points[0] == contact_points[1]);
  CHECK(pairs[0] == pairs[1]);
  REQUIRE(paths[0].size() == 30u * 512u);
  CHECK(paths[0] == paths[1]);
  // The pile moved: the comparison is not of bodies at rest.
  CHECK((paths[0].back() - cubes.back().mass.centroid).norm() > 1e-3);
}

TEST_CASE("physics-world: settings out of range are refused with the field's name", "[physics]") {
  PhysicsSettings s;
  s.contact_pool_size = 0;
  const auto pool = PhysicsWorld::create(s);
  REQUIRE_FALSE(pool);
  CHECK(pool.error().message.find("physics.contact_pool_size") != std::string::npos);
  s = PhysicsSettings{};
  s.hull_vertex_budget = 3;
  const auto budget = PhysicsWorld::create(s);
  REQUIRE_FALSE(budget);
  CHECK(budget.error().message.find("physics.hull_vertex_budget") != std::string::npos);
  for (const double margin : {-0.01, std::nan(""), HUGE_VAL}) {
    s = PhysicsSettings{};
    s.broadphase_margin = margin;
    const auto grown = PhysicsWorld::create(s);
    REQUIRE_FALSE(grown);
    CHECK(grown.error().message.find("physics.broadphase_margin") != std::string::npos);
  }
}
