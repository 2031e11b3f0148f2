// The dashboard's data from a store whose answer is known by construction: every commit of every
// series, the planted step as the change point, the regressed series first.

#include "harness/history/dashboard_data.h"
#include "tests/harness/history/store_contract.h"

#include <fmt/core.h>

using namespace shatter;
using namespace shatter::test;

TEST_CASE("dashboard data: every commit, the planted step, regressions first", "[history][dashboard]") {
  const std::string location = (history_scratch("dashboard") / "h.sqlite").string();
  HistoryStore store = open_or_fail(location);
  // 40 commits at scale 1, then 3 at scale 1.3: every timing series regresses at commit 40.
  for (int c = 0; c < 43; ++c) {
    const std::string sha = fmt::format("{:040x}", 0xabc000 + c);
    REQUIRE(store.record(synthetic_run(c < 40 ? 1.0 : 1.3, static_cast<std::uint64_t>(c + 1), sha, 1000 + c)));
  }
  Result<nlohmann::json> data = dashboard_data(store, {}, HistoryGateSettings{});
  REQUIRE(data);
  const nlohmann::json& d = *data;
  REQUIRE(d["commits"].size() == 43);
  CHECK(d["commits"][40]["sha"] == fmt::format("{:040x}", 0xabc000 + 40));
  REQUIRE(!d["series"].empty());
  bool seen_other = false;
  int regressed = 0;
  for (const nlohmann::json& s : d["series"]) {
    CHECK(s["points"].size() == 43);
    CHECK(s["points"][42][0] == 42);  // the commit index of the newest point
    const bool r = s.contains("newest") && s["newest"]["verdict"] == "regressed";
    if (r) {
      CHECK_FALSE(seen_other);  // regressions come first
      ++regressed;
      REQUIRE(s["changes"].size() >= 1);
      CHECK(s["changes"].back()["index"] == 40);
      CHECK(s["changes"].back()["change"].get<double>() == Approx(0.3).margin(0.05));
      CHECK(s["changes"].back()["kind"] == "regression");
    } else {
      seen_other = true;
    }
  }
  CHECK(regressed >= 4);  // worst frame and the two stages' CPU times of each cell, at least
}

TEST_CASE("dashboard data: the filters' fields, the settings, a window of commits", "[history][dashboard]") {
  const std::string location = (history_scratch("dashboard_fields") / "h.sqlite").string();
  HistoryStore store = open_or_fail(location);
  for (int c = 0; c < 6; ++c) {
    const std::string sha = fmt::format("{:040x}", 0xdef000 + c);
    REQUIRE(store.record(synthetic_run(1.0, static_cast<std::uint64_t>(c + 1), sha, 2000 + c)));
  }
  HistoryGateSettings gate;
  gate.change_points.window = 12;
  Result<nlohmann::json> data = dashboard_data(store, {}, gate);
  REQUIRE(data);
  CHECK((*data)["format"] == kDashboardDataFormat);
  CHECK((*data)["settings"]["window"] == 12);
  REQUIRE(!(*data)["series"].empty());
  Result<std::vector<SeriesInfo>> listed = store.list_series({});
  REQUIRE(listed);
  CHECK((*data)["series"].size() == listed->size());
  for (const nlohmann::json& s : (*data)["series"]) {
    CHECK(s["fracturer"] == "plane-slice");  // the synthetic cells run plane-slice/plane-slice/von-mises
    CHECK(s["id"].get<std::string>().size() == 16);
    CHECK(s["case"] == "synthetic");
  }
  // From the fourth commit on: three commits, every point's index into them.
  Result<nlohmann::json> recent = dashboard_data(store, {}, gate, 2003);
  REQUIRE(recent);
  REQUIRE((*recent)["commits"].size() == 3);
  CHECK((*recent)["commits"][0]["sha"] == fmt::format("{:040x}", 0xdef000 + 3));
  for (const nlohmann::json& s : (*recent)["series"]) {
    REQUIRE(s["points"].size() == 3);
    CHECK(s["points"][2][0] == 2);
  }
  // A filter that matches nothing: no series, no commits.
  SeriesFilter none;
  none.case_name = "no such case";
  Result<nlohmann::json> empty = dashboard_data(store, none, gate);
  REQUIRE(empty);
  CHECK((*empty)["series"].empty());
  CHECK((*empty)["commits"].empty());
}

TEST_CASE("dashboard data: commits of one second in their generation's order, and an acknowledged step is not open",
          "[history][dashboard]") {
  const std::string location = (history_scratch("dashboard_ack") / "h.sqlite").string();
  HistoryStore store = open_or_fail(location);
  // 40 commits in one second whose shas run against their generation, the last 3 at scale 1.3.
  std::vector<std::string> shas;
  for (int c = 0; c < 43; ++c) {
    shas.push_back(fmt::format("{:040x}", 0xfff000 - c));
    RunRecord run = synthetic_run(c < 40 ? 1.0 : 1.3, static_cast<std::uint64_t>(c + 1), shas.back(), 5000);
    run.commit.generation = c;
    REQUIRE(store.record(run));
  }
  Result<nlohmann::json> data = dashboard_data(store, {}, HistoryGateSettings{});
  REQUIRE(data);
  REQUIRE((*data)["commits"].size() == 43);
  for (int c = 0; c < 43; ++c) CHECK((*data)["commits"][c]["sha"] == shas[static_cast<std::size_t>(c)]);
  const nlohmann::json& first = (*data)["series"][0];
  REQUIRE(first["newest"]["verdict"] == "regressed");
  REQUIRE(first["changes"].back()["commit"] == shas[40]);
  // Acknowledged at the step: judged from there on, it is no longer an open regression.
  const std::int64_t id = static_cast<std::int64_t>(std::stoull(first["id"].get<std::string>(), nullptr, 16));
  REQUIRE(store.acknowledge({id, shas[40], "expected: more fragments", {}}));
  Result<nlohmann::json> after = dashboard_data(store, {}, HistoryGateSettings{});
  REQUIRE(after);
  bool found = false;
  for (const nlohmann::json& s : (*after)["series"])
    if (s["id"] == first["id"]) {
      found = true;
      CHECK(s["newest"]["verdict"] != "regressed");
      CHECK(s["newest"]["acknowledged"]["commit"] == shas[40]);
      CHECK(s["newest"]["acknowledged"]["note"] == "expected: more fragments");
      CHECK(s["changes"].size() == first["changes"].size());  // the change points are still drawn
    }
  CHECK(found);
}
