// Determinism of the stress models across builds and time: the bond figures (forces, moments,
// stresses, utilizations, broken flags), break order and falling clusters of the built-in wall case
// after propagation hash to the digests committed in tests/fixtures/determinism_hashes.json
// (tests/support/determinism_hash.h says how to regenerate them, and when that is allowed).

#include "algorithms/registry/registries.h"
#include "tests/support/builtin_registries.h"
#include "algorithms/stress/propagation.h"
#include "harness/cases/case_library.h"
#include "harness/pipeline/case_structure.h"
#include "tests/support/determinism_hash.h"

#include <catch2/catch.hpp>

#include <string>

using namespace shatter;

TEST_CASE("determinism: every stress model's evaluation of the wall matches the committed hashes",
          "[determinism][stress]") {
  Result<Case> c = find_case("wall");
  REQUIRE(c);
  Result<CaseStructure> structure = build_case_structure(*c, test::builtin_registries());
  REQUIRE(structure);
  Loads loads;
  loads.gravity = c->gravity;
  for (const std::string model_name : {"connection-count", "tresca", "von-mises"}) {
    const std::string key = "stress/" + model_name + "/wall";
    INFO(key);
    auto model = test::builtin_registries().stress_models.create(model_name);
    REQUIRE(model);
    auto p = propagate(**model, structure->graph, loads, c->material, {});
    REQUIRE(p);
    test::DeterminismHash digest;
    digest.add_int(static_cast<std::int64_t>(p->result.bonds.size()));
    for (const BondStress& s : p->result.bonds) {
      digest.add_double(s.normal_force);
      digest.add_double(s.shear_force);
      digest.add_double(s.bending_moment);
      digest.add_double(s.torsion);
      digest.add_double(s.sigma);
      digest.add_bool(s.tensile);
      digest.add_double(s.tau);
      digest.add_double(s.utilization);
      digest.add_bool(s.broken);
    }
    digest.add_int(static_cast<std::int64_t>(p->break_order.size()));
    for (const auto& round : p->break_order) digest.add_ints(round);
    digest.add_int(static_cast<std::int64_t>(p->result.falling_clusters.size()));
    for (const auto& cluster : p->result.falling_clusters) digest.add_ints(cluster);
    test::check_determinism_hash(key, digest);
  }
}
