// The run's offline setup checks the fragments the case's impacts reach as the runtime fracturer's
// inputs: every one of them is remembered clean, and each passes the full check run again without a
// memory (the independent verdict). Under --no-skip nothing is checked ahead, so the no-skip runs
// that prove the skips result-neutral (destruction_run_tests.cpp) compare against the checks in the
// frame.

#include "algorithms/core/mesh_fingerprint.h"
#include "algorithms/core/solid_check.h"
#include "algorithms/fracture/local_fracture.h"
#include "harness/pipeline/setup/run_setup.h"
#include "harness/pipeline/stage_plan.h"
#include "tests/support/builtin_registries.h"
#include "tests/support/prepared_case.h"

#include <catch2/catch.hpp>

#include <set>

using namespace shatter;

TEST_CASE("run setup: the fragments the impacts reach are checked as runtime inputs before frame 0", "[pipeline]") {
  const PreparedCase tower = test::prepared("tower");
  RunOptions options;
  options.prefracture_fragments = 40;
  const Registries registries = test::builtin_registries();
  RunState run(tower, options, registries);
  run.plan = plan_for(tower.spec.needs);
  REQUIRE(run_setup(run).ok());
  REQUIRE(run.checked_inputs != nullptr);
  REQUIRE_FALSE(tower.spec.impacts.empty());
  NearImpactOptions near;
  near.eligible = run.standing;
  std::set<int> reached;
  for (const ImpactEvent& e : tower.spec.impacts)
    for (const int f : fragments_near_impact(run.result.fragments, e.impact, near)) reached.insert(f);
  REQUIRE(reached.size() >= 2);
  for (const int f : reached) {
    const Mesh& mesh = run.result.fragments[static_cast<std::size_t>(f)].mesh;
    CHECK(check_solid(mesh, "test", nullptr).ok());
    CHECK(run.checked_inputs->remembers(mesh_fingerprint(mesh)));
  }
  // A fragment no impact reaches was not checked (the memory holds only what the event will need).
  int unchecked = 0;
  for (std::size_t f = 0; f < run.result.fragments.size(); ++f)
    if (!reached.count(static_cast<int>(f)) && !run.checked_inputs->remembers(mesh_fingerprint(run.result.fragments[f].mesh)))
      ++unchecked;
  CHECK(unchecked == static_cast<int>(run.result.fragments.size() - reached.size()));
  CHECK(run.result.setup.wall[static_cast<std::size_t>(Stage::runtime_fracture)] > 0.0);

  RunOptions no_skip = options;
  no_skip.no_skip = true;
  RunState full(tower, no_skip, registries);
  full.plan = plan_for(tower.spec.needs);
  REQUIRE(run_setup(full).ok());
  CHECK(full.checked_inputs == nullptr);
}
