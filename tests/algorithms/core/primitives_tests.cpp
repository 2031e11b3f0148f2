#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace shatter;

namespace {

/// Checks the invariants every primitive promises: closed, outward, surface-tagged, nothing for
/// validate_solid to fix.
void check_solid(Mesh mesh, std::size_t triangles, const std::string& name) {
  INFO(name);
  CHECK(mesh.triangle_count() == triangles);
  CHECK(mesh.tags.size() == mesh.triangles.size());
  CHECK(std::all_of(mesh.tags.begin(), mesh.tags.end(), [](FaceTag t) { return t == FaceTag::surface; }));
  CHECK(all_finite(mesh));
  CHECK(is_closed_and_oriented(mesh));
  CHECK(signed_volume(mesh) > 0.0);
  const Result<ValidationReport> report = validate_solid(mesh, name);
  REQUIRE(report.ok());
  CHECK_FALSE(report->flipped);
  CHECK(report->merged_duplicate_vertices == 0);
  CHECK(report->removed_unused_vertices == 0);
}

}  // namespace

TEST_CASE("primitives: every primitive is a valid outward solid", "[primitives]") {
  check_solid(make_box(Vec3(1, 2, 3), Vec3(4, 5, 6)), 12, "box");
  for (const int s : {3, 4, 17, 64}) {
    for (const int r : {2, 3, 16}) check_solid(make_sphere(1.5, s, r), 2 * s * (r - 1), "sphere");
    check_solid(make_cylinder(0.5, 2.0, s), 4 * s, "cylinder");
    check_solid(make_tube(0.25, 0.5, 2.0, s), 8 * s, "tube");
    check_solid(make_torus(2.0, 0.5, s, s + 1), 2 * s * (s + 1), "torus");
  }
}

TEST_CASE("primitives: box corners span the requested size around the centre", "[primitives]") {
  const Mesh box = make_box(Vec3(1, 2, 3), Vec3(4, 5, 6));
  REQUIRE(box.vertices.size() == 8);
  const Aabb bounds = bounding_box(box);
  CHECK(bounds.min == Vec3(3.5, 4.0, 4.5));
  CHECK(bounds.max == Vec3(4.5, 6.0, 7.5));
}

TEST_CASE("primitives: sphere vertices lie on the sphere, one vertex per pole", "[primitives]") {
  const Vec3 center(1, -2, 3);
  const Mesh sphere = make_sphere(2.5, 12, 7, center);
  CHECK(sphere.vertices.size() == 2 + 12 * 6);
  for (const Vec3& p : sphere.vertices) CHECK((p - center).norm() == Approx(2.5).epsilon(1e-14));
  const auto at_pole = [&](double z) {
    return std::count_if(sphere.vertices.begin(), sphere.vertices.end(),
                         [&](const Vec3& p) { return p.z() == center.z() + z; });
  };
  CHECK(at_pole(2.5) == 1);
  CHECK(at_pole(-2.5) == 1);
}

TEST_CASE("primitives: cylinder, tube and torus radii are as requested", "[primitives]") {
  for (const Vec3& p : make_cylinder(0.5, 2.0, 9).vertices) {
    const double rho = std::hypot(p.x(), p.y());
    CHECK((rho == 0.0 || rho == Approx(0.5).epsilon(1e-14)));
    CHECK(std::abs(p.z()) == Approx(1.0).epsilon(1e-14));
  }
  for (const Vec3& p : make_tube(0.25, 0.5, 2.0, 9).vertices) {
    const double rho = std::hypot(p.x(), p.y());
    CHECK((rho == Approx(0.25).epsilon(1e-14) || rho == Approx(0.5).epsilon(1e-14)));
  }
  for (const Vec3& p : make_torus(2.0, 0.5, 10, 6).vertices) {
    // Distance from the tube's centre circle equals the minor radius.
    CHECK(std::hypot(std::hypot(p.x(), p.y()) - 2.0, p.z()) == Approx(0.5).epsilon(1e-14));
  }
}
