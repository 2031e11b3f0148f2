// compare_cascades (harness/accuracy/cascade_accuracy.h): the bonds and fragments two cascades
// disagree on, counted on hand-made outcomes whose differences are known.
#include "harness/accuracy/cascade_accuracy.h"

#include <catch2/catch.hpp>

using namespace shatter;

namespace {

/// A cascade outcome over `bonds` bonds: `broken` flagged, `falling` clusters.
PropagationResult outcome(int bonds, std::vector<int> broken, std::vector<std::vector<int>> falling) {
  PropagationResult r;
  r.result.bonds.resize(static_cast<std::size_t>(bonds));
  for (const int b : broken) r.result.bonds[static_cast<std::size_t>(b)].broken = true;
  r.result.falling_clusters = std::move(falling);
  return r;
}

}  // namespace

TEST_CASE("cascade comparison: bonds and fragments in one outcome and not the other", "[accuracy][cascade]") {
  const PropagationResult exact = outcome(10, {0, 1, 2, 3}, {{4, 5}, {7}});
  SECTION("the same outcome") {
    const CascadeComparison d = compare_cascades(exact, exact, 8);
    CHECK(d.broken == 4);
    CHECK(d.reference_broken == 4);
    CHECK(d.broken_mismatch == 0);
    CHECK(d.falling == 3);
    CHECK(d.falling_mismatch == 0);
    CHECK(d.broken_share() == 0.0);
    CHECK(d.falling_share() == 0.0);
  }
  SECTION("fewer bonds broken, one more elsewhere, a cluster missing and another split") {
    // Broken {0, 1, 9}: 2 and 3 missing, 9 extra. Falling {4}, {5}: 7 missing; 4 and 5 both fall.
    const CascadeComparison d = compare_cascades(outcome(10, {0, 1, 9}, {{4}, {5}}), exact, 8);
    CHECK(d.broken == 3);
    CHECK(d.broken_mismatch == 3);
    CHECK(d.broken_share() == 0.75);
    CHECK(d.falling == 2);
    CHECK(d.reference_falling == 3);
    CHECK(d.falling_mismatch == 1);
    CHECK(d.falling_share() == 1.0 / 3.0);
  }
  SECTION("a reference that breaks nothing and drops nothing: shares over one") {
    const PropagationResult still = outcome(10, {}, {});
    const CascadeComparison d = compare_cascades(outcome(10, {2, 5}, {{1}}), still, 8);
    CHECK(d.broken_share() == 2.0);
    CHECK(d.falling_share() == 1.0);
  }
}
