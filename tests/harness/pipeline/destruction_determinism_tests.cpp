// Determinism of a whole destruction run across builds and time: one repetition of one fixed cell of
// the building case (pre-fracture, runtime fracture, bonds, stress cascade) hashes to the digest
// committed in tests/fixtures/determinism_hashes.json (tests/support/determinism_hash.h says how to
// regenerate it, and when that is allowed). Timings and physics poses are not hashed.

#include "tests/support/builtin_registries.h"
#include "harness/cases/case_library.h"
#include "harness/pipeline/destruction_run.h"
#include "tests/support/determinism_hash.h"

#include <catch2/catch.hpp>

#include <string>

using namespace shatter;

TEST_CASE("determinism: a short run of the building matches the committed hash", "[determinism][pipeline]") {
  Result<Case> c = find_case("building");
  REQUIRE(c);
  Result<PreparedCase> prepared = prepare_case(std::move(*c));
  REQUIRE(prepared);
  RunOptions options;
  options.prefracture_fragments = 30;
  options.runtime_fragments = 10;
  options.repetition = 0;
  options.frames = 20;  // the impact lands in frame 10
  options.partition_samples = 0;
  Result<RunResult> r = run_destruction(*prepared, options, test::builtin_registries());
  INFO((r ? std::string() : r.error().message));
  REQUIRE(r);
  REQUIRE_FALSE(r->hit.empty());

  test::DeterminismHash digest;
  digest.add_fragments(r->fragments);
  digest.add_int(r->graph.bond_count());
  for (const Bond& b : r->graph.bonds) {
    digest.add_int(b.a);
    digest.add_int(b.b);
    digest.add_double(b.area);
  }
  digest.add_int(static_cast<std::int64_t>(r->broken.size()));
  for (const std::uint8_t broken : r->broken) digest.add_byte(broken);
  digest.add_ints(r->hit);
  digest.add_int(static_cast<std::int64_t>(r->pieces.size()));
  for (const auto& pieces : r->pieces) digest.add_fragments(pieces);
  digest.add_int(static_cast<std::int64_t>(r->falling_clusters.size()));
  for (const auto& cluster : r->falling_clusters) digest.add_ints(cluster);
  test::check_determinism_hash("destruction/building/30x10/repetition-0", digest);
}
