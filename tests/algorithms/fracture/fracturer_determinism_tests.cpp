// Determinism across builds and time, not only within one process: every built-in fracturer's
// fragments (positions bit for bit, triangles, tags, in order) on fixed solids, seeds and counts hash
// to the digests committed in tests/fixtures/determinism_hashes.json (tests/support/determinism_hash.h
// says how to regenerate them, and when that is allowed).

#include "algorithms/core/primitives.h"
#include "algorithms/registry/registries.h"
#include "tests/support/builtin_registries.h"
#include "tests/support/determinism_hash.h"
#include "tests/support/mesh_fixtures.h"
#include "tests/support/shapes.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace shatter;

namespace {

/// The fracturers whose digests are committed: every registered fracturer but an exact reference
/// (Fracturer::exact_reference). A new built-in fracturer adds its digests to the fixture.
// Not the exact reference: it rounds lazy exact numbers to doubles through their interval
// approximations, whose last bits differ between optimisation levels (the release and sanitizer builds
// disagree on the torus and elephant.off). Its determinism within one build is the conformance test's.
std::vector<std::string> hashed_fracturers(const Registries& r) {
  std::vector<std::string> out;
  for (const std::string& name : r.fracturers.names()) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    if (!(*fracturer)->exact_reference()) out.push_back(name);
  }
  return out;
}

/// A downward hit at the centre of the top of `solid`'s bounding box, radius a tenth of its diagonal.
Impact impact_on(const Mesh& solid) {
  Vec3 lo = solid.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& v : solid.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  Impact impact;
  impact.point = Vec3((lo.x() + hi.x()) / 2, (lo.y() + hi.y()) / 2, hi.z());
  impact.direction = Vec3(0, 0, -1);
  impact.impulse = 500;
  impact.radius = 0.1 * (hi - lo).norm();
  return impact;
}

/// Checks the digests of every hashed fracturer on `solid` (named `solid_name` in the keys), with
/// and without an impact.
void check_fracturers_on(const std::string& solid_name, const Mesh& solid) {
  const Registries r = test::builtin_registries();
  for (const std::string& name : hashed_fracturers(r)) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    for (const bool with_impact : {false, true}) {
      FractureParams params;
      params.fragments = 8;
      params.seed = 7;
      if (with_impact) params.impact = impact_on(solid);
      const std::string key = "fracture/" + name + "/" + solid_name + (with_impact ? "/impact" : "/no-impact");
      INFO(key);
      auto fragments = (*fracturer)->fracture(solid, params);
      REQUIRE(fragments.ok());
      test::DeterminismHash digest;
      digest.add_fragments(*fragments);
      test::check_determinism_hash(key, digest);
    }
  }
}

}  // namespace

// A flat box rather than the unit cube: fem-lite's default grid of 16 cells along the longest axis
// makes the cube its most expensive solve (16^3 cells), which the box cuts to an eighth.
TEST_CASE("determinism: every fracturer's fragments of a box match the committed hashes",
          "[determinism][conformance]") {
  check_fracturers_on("box-2x1x0.5", make_box(Vec3(2, 1, 0.5)));
}

TEST_CASE("determinism: every fracturer's fragments of a U-shaped prism match the committed hashes",
          "[determinism][conformance]") {
  check_fracturers_on("u-shape", test::make_u_shape());
}

TEST_CASE("determinism: every fracturer's fragments of a torus match the committed hashes",
          "[determinism][conformance]") {
  check_fracturers_on("torus", make_torus(2.0, 0.5, 24, 12));
}

TEST_CASE("determinism: every fracturer's fragments of elephant.off match the committed hashes",
          "[determinism][conformance][real-meshes]") {
  const auto elephant = test::load_fixture_mesh("elephant.off");
  if (!elephant) return;
  check_fracturers_on("elephant", *elephant);
}
