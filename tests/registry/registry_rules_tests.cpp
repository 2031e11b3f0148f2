// Registry::problem: the rules a registration must keep (unique names without white space, one-line
// descriptions), reported rather than asserted, so that a plugin's debug build cannot stop the host.

#include "algorithms/core/registry.h"
#include "algorithms/registry/registries.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>

using namespace shatter;
using Catch::Matchers::Contains;

namespace {

Result<std::unique_ptr<Fracturer>> never(const PluginSettings&) { return Error{"not created in this test"}; }

}  // namespace

TEST_CASE("registry: a broken registration is reported by problem(), not asserted in add()", "[registry]") {
  Registry<Fracturer> r;
  r.add("first", "one line", {}, never);
  CHECK(r.problem().empty());
  SECTION("a name twice") {
    r.add("first", "again", {}, never);
    CHECK(r.problem() == "fracturer 'first' is registered twice");
  }
  SECTION("a description of two lines") {
    r.add("second", "two\nlines", {}, never);
    CHECK_THAT(r.problem(), Contains("'second' has a description of more than one line"));
  }
  SECTION("a name with white space, an empty name") {
    r.add("with space", "one line", {}, never);
    CHECK_THAT(r.problem(), Contains("name 'with space' is empty or holds white space"));
    Registry<Fracturer> empty;
    empty.add("", "one line", {}, never);
    CHECK_THAT(empty.problem(), Contains("name '' is empty"));
  }
}

TEST_CASE("registry: the built-in registrations keep the rules", "[registry]") {
  Registries r;
  register_all(r);
  CHECK(r.fracturers.problem().empty());
  CHECK(r.stress_models.problem().empty());
  CHECK(r.fracturers.names().size() >= 4);
  CHECK(r.stress_models.names().size() >= 3);
}
