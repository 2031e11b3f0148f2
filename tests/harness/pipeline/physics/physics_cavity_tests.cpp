// A fragment with a cavity gets a collider with the mass and inertia of the material, not of its hull.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "harness/pipeline/physics/physics_world.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace shatter;

TEST_CASE("physics-world: a hollow fragment has the mass and inertia of its material", "[physics][cavities]") {
  Fragment f;
  f.mesh = make_box(Vec3(2, 2, 2));
  Mesh cavity = make_box(Vec3(1, 1, 1));
  const auto offset = static_cast<std::int32_t>(f.mesh.vertices.size());
  for (const Vec3& v : cavity.vertices) f.mesh.add_vertex(v);
  for (const Triangle& t : cavity.triangles) f.mesh.add_triangle(t[0] + offset, t[2] + offset, t[1] + offset, FaceTag::surface);
  f.mass = mass_properties(f.mesh);
  PhysicsSettings settings;
  settings.gravity = Vec3::Zero();
  PhysicsWorld world(settings);
  const double density = 1000.0;
  const int body = world.add_fragment(f, density);
  // 2 x 2 x 2 box less a 1 x 1 x 1 box: volume 7, I = m (a^2 + b^2) / 12 of each, subtracted.
  CHECK(world.mass(body) == Approx(density * 7.0).epsilon(1e-6));
  const Vec3 moments = world.principal_inertia(body);
  const double expected = density * (8.0 * 8.0 / 12.0 - 1.0 * 2.0 / 12.0);
  for (int k = 0; k < 3; ++k) CHECK(moments[k] == Approx(expected).epsilon(1e-5));
}
