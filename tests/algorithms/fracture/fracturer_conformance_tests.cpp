// Every registered fracturer over the same solids, with and without an impact: the shared contract of
// algorithms/fracture/fracturer.h (closed, oriented, finite fragments that partition the input and
// conserve its volume, at least the requested count, the same output for the same seed).

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/solid_check.h"
#include "tests/support/builtin_registries.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace shatter;

TEST_CASE("conformance: every registered fracturer keeps the fracture contract", "[conformance]") {
  struct NamedSolid {
    std::string name;
    Mesh mesh;
  };
  const std::vector<NamedSolid> solids = {{"box", make_box(Vec3(2, 1, 0.5))},
                                          {"sphere", make_sphere(1.0, 16, 8)},
                                          {"torus", make_torus(2.0, 0.5, 24, 12)},
                                          {"U shape", test::make_u_shape()}};
  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    CHECK((*fracturer)->name() == name);
    for (const NamedSolid& solid : solids) {
      const MassProperties mass = mass_properties(solid.mesh);
      for (const bool with_impact : {false, true}) {
        INFO(name << " on " << solid.name << (with_impact ? " with an impact" : ""));
        FractureParams params;
        params.fragments = 6;
        params.seed = 17;
        if (with_impact) {
          Impact impact;
          impact.point = mass.centroid + Vec3(0.2, 0.1, 0.0);
          impact.direction = Vec3(0, 0, -1);
          impact.impulse = 500;
          impact.radius = 0.3;
          params.impact = impact;
        }
        auto a = (*fracturer)->fracture(solid.mesh, params);
        auto b = (*fracturer)->fracture(solid.mesh, params);
        REQUIRE(a.ok());
        REQUIRE(b.ok());
        CHECK(static_cast<int>(a->size()) >= params.fragments);
        for (const Fragment& f : *a) {
          CHECK(is_closed_and_oriented(f.mesh));
          CHECK(all_finite(f.mesh));
          CHECK(f.mass.volume > 0);
          CHECK(f.mass.centroid.allFinite());
          CHECK(f.mesh.tags.size() == f.mesh.triangles.size());
        }
        const FractureMetrics m = fracture_metrics(solid.mesh, mass, *a, params.fragments,
                                                   FractureMetricsOptions{.partition_samples = 500, .seed = 3});
        CHECK(m.volume_error <= 1e-9);
        CHECK(m.partition_error == 0.0);
        CHECK(m.area_error <= 1e-9);
        REQUIRE(a->size() == b->size());
        for (std::size_t i = 0; i < a->size(); ++i) {
          CHECK((*a)[i].mesh.vertices == (*b)[i].mesh.vertices);
          CHECK((*a)[i].mesh.triangles == (*b)[i].mesh.triangles);
        }
      }
    }
  }
}

TEST_CASE("conformance: every fragment passes the acceptance rule and fractures again with every fracturer",
          "[conformance][acceptance]") {
  struct NamedSolid {
    std::string name;
    Mesh mesh;
  };
  Mesh hollow = make_sphere(1.0, 16, 8);
  {
    const Mesh cavity = make_sphere(0.5, 12, 6);
    const auto offset = static_cast<std::int32_t>(hollow.vertices.size());
    for (const Vec3& v : cavity.vertices) hollow.add_vertex(v);
    for (const Triangle& t : cavity.triangles) hollow.add_triangle(t[0] + offset, t[2] + offset, t[1] + offset, FaceTag::surface);
  }
  const std::vector<NamedSolid> solids = {{"box", make_box(Vec3(2, 1, 0.5))},
                                          {"sphere", make_sphere(1.0, 16, 8)},
                                          {"torus", make_torus(2.0, 0.5, 24, 12)},
                                          {"U shape", test::make_u_shape()},
                                          {"hollow sphere", hollow}};
  const Registries r = test::builtin_registries();
  const std::vector<std::string> names = r.fracturers.names();
  for (const std::string& name : names) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    for (const NamedSolid& solid : solids) {
      REQUIRE(check_solid(solid.mesh, solid.name, nullptr));
      for (const std::uint64_t seed : {3u, 11u}) {
        FractureParams params;
        params.fragments = 8;
        params.seed = seed;
        auto fragments = (*fracturer)->fracture(solid.mesh, params);
        INFO(name << " on " << solid.name << ", seed " << seed);
        REQUIRE(fragments.ok());
        for (std::size_t i = 0; i < fragments->size(); ++i) {
          const Mesh& piece = (*fragments)[i].mesh;
          const Status accepted = check_solid(piece, "fragment " + std::to_string(i), nullptr);
          // The exact reference's fragments are its exact pieces rounded to doubles: where a cut
          // passes within rounding distance of a vertex, rounding can make two triangles touch. A
          // known gap of the reference (docs/repair.md), not of the fracturers measured.
          const bool rounding_gap = (*fracturer)->exact_reference() && !accepted &&
                                    accepted.error().message.find("intersects itself") != std::string::npos;
          CHECK((accepted.ok() || rounding_gap));
          if (!accepted) {
            WARN(accepted.error().message);
            continue;
          }
          if (i >= 3) continue;  // fracture the first few again with every fracturer
          for (const std::string& other : names) {
            auto again = r.fracturers.create(other);
            REQUIRE(again.ok());
            FractureParams more;
            more.fragments = 4;
            more.seed = seed + i;
            auto pieces = (*again)->fracture(piece, more);
            INFO("fragment " << i << " fractured again by " << other);
            CHECK(pieces.ok());
            if (!pieces) WARN(pieces.error().message);
            else
              for (const Fragment& p : *pieces) CHECK(check_solid(p.mesh, other, nullptr).ok());
          }
        }
      }
    }
  }
}
