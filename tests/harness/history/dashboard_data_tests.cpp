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
