// The history store on a real PostgreSQL 15 server (started by the CTest fixture `postgres`): the
// same contract as SQLite (store_contract.h), and what only a server has: a connection dropped in the
// middle of a record. Each test works in a schema of its own, made fresh.

#include "tests/harness/history/store_contract.h"
#include "tests/support/postgres_server.h"

#include <libpq-fe.h>

using namespace shatter;
using namespace shatter::test;

namespace {

/// The test server's URL with `schema` (made empty) as the search path of every connection.
std::string postgres_store(const std::string& schema) {
  const std::string url = test_postgres_url();
  PGconn* conn = PQconnectdb(url.c_str());
  REQUIRE(PQstatus(conn) == CONNECTION_OK);
  PQsetNoticeProcessor(conn, [](void*, const char*) {}, nullptr);  // "schema does not exist, skipping"
  const std::string sql = "DROP SCHEMA IF EXISTS " + schema + " CASCADE; CREATE SCHEMA " + schema;
  PGresult* res = PQexec(conn, sql.c_str());
  INFO(PQerrorMessage(conn));
  CHECK(PQresultStatus(res) == PGRES_COMMAND_OK);
  PQclear(res);
  PQfinish(conn);
  return url + "?options=-csearch_path%3D" + schema;
}

}  // namespace

TEST_CASE("postgres store: a run reads back exactly and records once", "[postgres][history]") {
  check_round_trip(postgres_store("round_trip"));
}

TEST_CASE("postgres store: an older schema is brought forward, a newer one refused", "[postgres][history]") {
  check_migrations(postgres_store("migrations"));
}

TEST_CASE("postgres store: two recorders at once both land", "[postgres][history]") {
  check_concurrent_recorders(postgres_store("concurrent"), history_scratch("postgres_concurrent"));
}

TEST_CASE("postgres store: a recorder killed at any moment leaves the store whole", "[postgres][history]") {
  check_killed_recorder(postgres_store("killed"), history_scratch("postgres_killed"));
}

TEST_CASE("postgres store: bad input is one line, exit 2, the store unchanged", "[postgres][history]") {
  check_bad_input_leaves_store(postgres_store("bad_input"), history_scratch("postgres_bad_input"));
}

TEST_CASE("postgres store: a connection dropped during a record leaves nothing of it", "[postgres][history]") {
  const std::string location = postgres_store("dropped");
  HistoryStore recorder = open_or_fail(location);
  HistoryStore watcher = open_or_fail(location);
  Result<std::vector<SqlRow>> pid = recorder.connection().query("SELECT pg_backend_pid()");
  REQUIRE(pid);
  // The server ends the recorder's session (as a restart or a network cut would).
  REQUIRE(watcher.connection().query("SELECT pg_terminate_backend(CAST(? AS integer))", {sql_int(pid->front()[0])}));
  const Result<bool> added = recorder.record(synthetic_run(1.0, 1, std::string(40, 'd'), 10));
  REQUIRE_FALSE(added);
  CHECK(added.error().message.find("postgresql://127.0.0.1:") == 0);
  CHECK(added.error().message.find('\n') == std::string::npos);
  CHECK(run_count(watcher) == 0);
  CHECK(measurement_count(watcher) == 0);
  // A connection dropped after the run's first rows were sent: the transaction never commits.
  HistoryStore second = open_or_fail(location);
  REQUIRE(second.connection().begin_write());
  REQUIRE(second.connection().query("INSERT INTO sb_commits (sha, parents, branch, dirty, commit_time) VALUES (?, '', '', 0, 1)",
                                    {std::string(40, 'e')}));
  Result<std::vector<SqlRow>> second_pid = second.connection().query("SELECT pg_backend_pid()");
  REQUIRE(second_pid);
  REQUIRE(watcher.connection().query("SELECT pg_terminate_backend(CAST(? AS integer))", {sql_int(second_pid->front()[0])}));
  CHECK_FALSE(second.connection().commit());
  Result<std::vector<SqlRow>> commits = watcher.connection().query("SELECT count(*) FROM sb_commits");
  REQUIRE(commits);
  CHECK(sql_int(commits->front()[0]) == 0);
}
