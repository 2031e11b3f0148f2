// Result context block (DESIGN.md section 7) and its fingerprint: what changes it and what does not.

#include "harness/results/run_context.h"

#include <catch2/catch.hpp>

#include <regex>
#include <thread>

using namespace shatter;

namespace {

RunContext sample_context() {
  RunContext c;
  c.commit = "0123456789ab";
  c.build_type = "Release";
  c.compiler = "GNU 12.2.0";
  c.flags = "-O3 -DNDEBUG";
  c.cgal_version = "5.5.1";
  c.eigen_version = "3.4.0";
  c.bullet_version = "3.24";
  c.cpu_model = "Example CPU @ 3.00GHz";
  c.cores = 8;
  c.date = "2026-11-22T06:31:56Z";
  c.hostname = "bench-01";
  c.fingerprint = context_fingerprint(c);
  return c;
}

}  // namespace

TEST_CASE("run context: the fingerprint is stable and 16 hex digits", "[results]") {
  const RunContext c = sample_context();
  CHECK(context_fingerprint(c) == context_fingerprint(sample_context()));
  CHECK(std::regex_match(c.fingerprint, std::regex("[0-9a-f]{16}")));
}

TEST_CASE("run context: the fingerprint changes with what decides the timings", "[results]") {
  const RunContext base = sample_context();
  const auto changed = [&](auto edit) {
    RunContext c = base;
    edit(c);
    return context_fingerprint(c) != base.fingerprint;
  };
  CHECK(changed([](RunContext& c) { c.compiler = "Clang 16.0.6"; }));
  CHECK(changed([](RunContext& c) { c.cpu_model = "Other CPU"; }));
  CHECK(changed([](RunContext& c) { c.cores = 4; }));
  CHECK(changed([](RunContext& c) { c.build_type = "Debug"; }));
  CHECK(changed([](RunContext& c) { c.flags = "-O2"; }));
  CHECK(changed([](RunContext& c) { c.cgal_version = "6.0"; }));
  CHECK(changed([](RunContext& c) { c.eigen_version = "3.3.9"; }));
  CHECK(changed([](RunContext& c) { c.bullet_version = ""; }));
  // Fields must not run into each other: moving text from one to the next is a different context.
  CHECK(changed([](RunContext& c) { c.build_type = "ReleaseGNU"; c.compiler = " 12.2.0"; }));
}

TEST_CASE("run context: the commit leaves the fingerprint alone (a gate compares commits)", "[results]") {
  RunContext c = sample_context();
  const std::string before = context_fingerprint(c);
  c.commit = "ba9876543210";
  CHECK(context_fingerprint(c) == before);
}

TEST_CASE("run context: the date and host name leave the fingerprint alone", "[results]") {
  RunContext c = sample_context();
  c.date = "2030-01-01T00:00:00Z";
  c.hostname = "another-machine";
  CHECK(context_fingerprint(c) == sample_context().fingerprint);
}

TEST_CASE("run context: this process's context", "[results]") {
  const RunContext c = current_context();
  CHECK(c.fingerprint == context_fingerprint(c));
  CHECK(c.cores == std::thread::hardware_concurrency());
  CHECK_FALSE(c.build_type.empty());
  CHECK_FALSE(c.compiler.empty());
  CHECK_FALSE(c.eigen_version.empty());
  CHECK(std::regex_match(c.date, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  // Build values do not depend on when the context is taken.
  CHECK(current_context().fingerprint == c.fingerprint);
}

TEST_CASE("run context: JSON round trip through text", "[results]") {
  const RunContext c = sample_context();
  const nlohmann::ordered_json j = to_json(c);
  CHECK(j.begin().key() == "commit");
  CHECK(j["cores"] == 8);
  const Result<RunContext> back = context_from_json(nlohmann::json::parse(j.dump()));
  REQUIRE(back.ok());
  CHECK(to_json(*back) == j);
  CHECK(back->cores == 8);
  CHECK(back->fingerprint == c.fingerprint);

  const Result<RunContext> now = context_from_json(nlohmann::json::parse(to_json(current_context()).dump()));
  REQUIRE(now.ok());
  CHECK(context_fingerprint(*now) == now->fingerprint);
}

TEST_CASE("run context: bad JSON names the key", "[results]") {
  const nlohmann::json good = nlohmann::json::parse(to_json(sample_context()).dump());
  const auto error_of = [](const nlohmann::json& j) {
    const Result<RunContext> r = context_from_json(j);
    REQUIRE_FALSE(r.ok());
    return r.error().message;
  };
  CHECK(error_of(nlohmann::json::array()) == "context: expected an object");
  nlohmann::json j = good;
  j.erase("compiler");
  CHECK(error_of(j) == "context.compiler: missing");
  j = good;
  j["cpu_model"] = 3;
  CHECK(error_of(j) == "context.cpu_model: expected a string");
  j = good;
  j["cores"] = -1;
  CHECK_THAT(error_of(j), Catch::StartsWith("context.cores:"));
  j["cores"] = 2.5;
  CHECK_THAT(error_of(j), Catch::StartsWith("context.cores:"));
  j.erase("cores");
  CHECK(error_of(j) == "context.cores: missing");
}
