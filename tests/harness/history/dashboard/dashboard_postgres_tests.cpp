// The dashboard's data from a PostgreSQL store (the CTest fixture `postgres`): the same answer as from
// SQLite, through the command line too.

#include "harness/history/dashboard_data.h"
#include "tests/harness/history/store_contract.h"
#include "tests/support/postgres_server.h"

#include <fmt/core.h>
#include <libpq-fe.h>

using namespace shatter;
using namespace shatter::test;

namespace {

/// The test server's URL with the schema `dashboard_test` (made empty) as every connection's search path.
std::string fresh_postgres_store() {
  const std::string url = test_postgres_url();
  PGconn* conn = PQconnectdb(url.c_str());
  REQUIRE(PQstatus(conn) == CONNECTION_OK);
  PQsetNoticeProcessor(conn, [](void*, const char*) {}, nullptr);
  PGresult* res = PQexec(conn, "DROP SCHEMA IF EXISTS dashboard_test CASCADE; CREATE SCHEMA dashboard_test");
  CHECK(PQresultStatus(res) == PGRES_COMMAND_OK);
  PQclear(res);
  PQfinish(conn);
  return url + "?options=-csearch_path%3Ddashboard_test";
}

}  // namespace

TEST_CASE("postgres store: the dashboard's data and page", "[postgres][history][dashboard]") {
  const std::string location = fresh_postgres_store();
  {
    HistoryStore store = open_or_fail(location);
    for (int c = 0; c < 43; ++c)
      REQUIRE(store.record(synthetic_run(c < 40 ? 1.0 : 1.3, static_cast<std::uint64_t>(c + 1),
                                         fmt::format("{:040x}", 0xbee000 + c), 3000 + c)));
    Result<nlohmann::json> data = dashboard_data(store, {}, HistoryGateSettings{});
    REQUIRE(data);
    REQUIRE((*data)["commits"].size() == 43);
    REQUIRE(!(*data)["series"].empty());
    const nlohmann::json& first = (*data)["series"][0];
    CHECK(first["points"].size() == 43);
    CHECK(first["newest"]["verdict"] == "regressed");
    CHECK(first["changes"].back()["index"] == 40);
  }
  const auto out = history_scratch("dashboard_postgres") / "dashboard";
  const CliRun r = run_cli_argv({"history", "report", "--db", location, "--out", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("over 43 commits") != std::string::npos);
  CHECK(std::filesystem::file_size(out / "dashboard.html") > 1000);
}
