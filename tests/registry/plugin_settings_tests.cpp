// Plugin settings: factories refuse unknown keys and out-of-range values by name, and the stress
// solver's settings change what the solver does.

#include "algorithms/registry/registries.h"
#include "algorithms/stress/propagation.h"
#include "fixtures/structures.h"
#include "tests/support/builtin_registries.h"

#include <catch2/catch.hpp>

#include <string>

using namespace shatter;

TEST_CASE("settings: unknown keys and bad values are errors naming the key and the range", "[registry]") {
  const Registries r = test::builtin_registries();
  const auto error_of = [](auto result) { return result ? std::string() : result.error().message; };
  CHECK(error_of(r.fracturers.create("voronoi", {{"colour", 1.0}})) ==
        "voronoi: settings.colour: unknown key (known: impact_share, max_draws_per_site, leaf_cells)");
  CHECK(error_of(r.fracturers.create("plane-slice", {{"resolution", 8.0}})) ==
        "plane-slice: settings.resolution: unknown key (known: none)");
  CHECK(error_of(r.fracturers.create("fem-lite", {{"resolution", 1.0}})) ==
        "fem-lite: settings.resolution: must be in [2, 128], got 1");
  CHECK(error_of(r.fracturers.create("fem-lite", {{"resolution", 8.5}})) ==
        "fem-lite: settings.resolution: expected an integer, got 8.5");
  CHECK(error_of(r.stress_models.create("tresca", {{"tolerance", 0.0}})) ==
        "tresca: settings.tolerance: must be in (0, 1], got 0");
  CHECK(error_of(r.stress_models.create("von-mises", {{"cg_only", 1.0}})) ==
        "von-mises: settings.cg_only: expected true or false, got number");
  CHECK(error_of(r.stress_models.create("connection-count", {{"min_support_fraction", 2.0}})) ==
        "connection-count: settings.min_support_fraction: must be in [0, 1], got 2");
  CHECK(r.fracturers.create("voronoi", {{"impact_share", 0.25}, {"leaf_cells", 4.0}}).ok());
  CHECK(r.fracturers.create("fem-lite", {{"resolution", 8.0}}).ok());
}

TEST_CASE("settings: every plugin documents its keys, and its defaults are accepted", "[registry]") {
  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    INFO(name);
    CHECK(r.fracturers.create(name).ok());
    for (const SettingDoc& d : r.fracturers.settings(name)) CHECK_FALSE(d.range.empty());
  }
  for (const std::string& name : r.stress_models.names()) {
    INFO(name);
    CHECK(r.stress_models.create(name).ok());
  }
  CHECK(r.fracturers.settings("fem-lite").front().accuracy_sweep == std::vector<double>{8, 16, 32});
}

TEST_CASE("settings: the stress tolerance and iteration cap reach the solver", "[registry][stress]") {
  const Registries r = test::builtin_registries();
  // A 4 m cantilever of 8 slabs, anchored at x = 0.
  const SupportGraph g = fixtures::graph_of(fixtures::sliced_box({4, 0.5, 0.5}, {2, 0, 0.25}, fixtures::planes_at(0, fixtures::even_cuts(0, 4, 8))),
                                        {fixtures::box_region({-1, -1, -1}, {0.001, 1, 1})}, 2400.0);
  Loads loads;
  Material material;
  material.tensile_strength = material.compressive_strength = material.shear_strength = 1e12;  // nothing breaks

  Result<std::unique_ptr<StressModel>> plain = r.stress_models.create("von-mises");
  REQUIRE(plain.ok());
  Result<StressResult> ok = (*plain)->evaluate(g, loads, material);
  REQUIRE(ok.ok());
  CHECK(ok->report.converged);

  // A tolerance no solve in double precision can meet (convergence is judged against the larger of
  // tolerance and cg_tolerance): the same solve is reported not converged.
  Result<std::unique_ptr<StressModel>> strict =
      r.stress_models.create("von-mises", {{"tolerance", 1e-300}, {"cg_tolerance", 1e-300}});
  REQUIRE(strict.ok());
  Result<StressResult> tight = (*strict)->evaluate(g, loads, material);
  REQUIRE(tight.ok());
  CHECK_FALSE(tight->report.converged);
  CHECK(tight->report.tolerance == 1e-300);

  // CG everywhere with one iteration allowed stops short of its tolerance.
  Result<std::unique_ptr<StressModel>> capped =
      r.stress_models.create("tresca", {{"cg_only", true}, {"max_iterations", 1.0}, {"cg_tolerance", 1e-12}});
  REQUIRE(capped.ok());
  Result<StressResult> short_run = (*capped)->evaluate(g, loads, material);
  REQUIRE(short_run.ok());
  CHECK_FALSE(short_run->report.converged);
  CHECK(short_run->report.iterations >= 1);
}
