// Results files as runs of the history: the series each kind of file measures, rows that measured
// nothing, repeated rows, and values the analysis could not hold.

#include "harness/history/results_run.h"
#include "tests/support/history_fixtures.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace shatter;
using namespace shatter::test;

namespace {

nlohmann::json table_file() {
  return nlohmann::json{{"schema_version", 1},
                        {"kind", "table"},
                        {"context", to_json(history_context("0123456789ab"))},
                        {"repetitions", 2},
                        {"passed", true},
                        {"rows",
                         {{{"mesh", "sphere.off"}, {"algorithm", "plane-slice"}, {"fragments", 5}, {"samples_ms", {1.0, 2.0}},
                           {"figures", {{"volume_error", 1e-15}, {"all_closed", true}}}},
                          {{"mesh", "sphere.off"}, {"algorithm", "voronoi"}, {"fragments", 5}, {"refused", "not a solid"}},
                          {{"mesh", "sphere.off"}, {"algorithm", "plane-slice"}, {"fragments", 5}, {"samples_ms", {3.0}}}}}};
}

}  // namespace

TEST_CASE("results run: a table's refused row is left out and a repeated row pooled", "[history][results-run]") {
  Result<RunRecord> run = run_from_results_text(table_file().dump(), "t.json");
  REQUIRE(run);
  CHECK(run->kind == "table");
  int times = 0;
  for (const Measurement& m : run->measurements) {
    CHECK(m.series.case_name == "sphere.off");
    CHECK(m.series.subject == "plane-slice 5 fragments");  // nothing of the refused voronoi row
    if (m.series.metric == "time_ms") {
      ++times;
      CHECK(m.samples == std::vector<double>{1.0, 2.0, 3.0});
    }
  }
  CHECK(times == 1);
}

TEST_CASE("results run: values the analysis could not hold are refused", "[history][results-run]") {
  nlohmann::json t = table_file();
  t["rows"][0]["samples_ms"] = {1.0, 1e200};
  Result<RunRecord> run = run_from_results_text(t.dump(), "t.json");
  REQUIRE_FALSE(run);
  CHECK(run.error().message.find("t.json: sphere.off plane-slice 5 fragments fracture time_ms: 1e+200 is out of range") == 0);
  t["rows"][0]["samples_ms"] = {1.0, 2.0};
  t["passed"] = "yes";
  Result<RunRecord> bad = run_from_results_text(t.dump(), "t.json");
  REQUIRE_FALSE(bad);
  CHECK(bad.error().message == "t.json: passed: expected true or false");
}

TEST_CASE("results run: grids of other settings are other series", "[history][results-run]") {
  Result<RunRecord> a = run_from_results_text(synthetic_grid_text(1.0, 0.01, 1, "0123456789ab"), "a.json");
  Result<RunRecord> b = run_from_results_text(synthetic_grid_text(1.0, 0.01, 1, "0123456789ab", 2, 9), "b.json");
  nlohmann::json other = nlohmann::json::parse(synthetic_grid_text(1.0, 0.01, 1, "0123456789ab"));
  other["threads"] = 2;
  Result<RunRecord> c = run_from_results_text(other.dump(), "c.json");
  REQUIRE(a);
  REQUIRE(b);
  REQUIRE(c);
  CHECK(a->fingerprint == b->fingerprint);  // more repetitions: more samples of the same series
  CHECK(a->fingerprint != c->fingerprint);  // another thread count: other series
  CHECK(a->fingerprint.starts_with(history_context("x").fingerprint + "-"));
}
