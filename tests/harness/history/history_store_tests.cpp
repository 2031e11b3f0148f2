// The history store on SQLite: the contract every backend keeps (store_contract.h), and what only a
// file has: another process's lock, another program's database, a file that is no database.

#include "tests/harness/history/store_contract.h"

#include <sqlite3.h>

#include <chrono>

using namespace shatter;
using namespace shatter::test;

TEST_CASE("sqlite store: a run reads back exactly and records once", "[history][store]") {
  check_round_trip((history_scratch("sqlite_round_trip") / "h.sqlite").string());
}

TEST_CASE("sqlite store: an older schema is brought forward, a newer one refused", "[history][store]") {
  check_migrations((history_scratch("sqlite_migrations") / "h.sqlite").string());
}

TEST_CASE("sqlite store: two recorders at once both land", "[history][store]") {
  const auto dir = history_scratch("sqlite_concurrent");
  check_concurrent_recorders((dir / "h.sqlite").string(), dir);
}

TEST_CASE("sqlite store: a recorder killed at any moment leaves the store whole", "[history][store]") {
  const auto dir = history_scratch("sqlite_killed");
  check_killed_recorder((dir / "h.sqlite").string(), dir);
}

TEST_CASE("sqlite store: bad input is one line, exit 2, the store unchanged", "[history][store]") {
  const auto dir = history_scratch("sqlite_bad_input");
  check_bad_input_leaves_store((dir / "h.sqlite").string(), dir);
}

TEST_CASE("sqlite store: a file locked by another writer is one line, exit 2, after the timeout", "[history][store]") {
  const auto dir = history_scratch("sqlite_locked");
  const std::string db_path = (dir / "h.sqlite").string();
  const std::vector<std::string> shas = make_commits(dir / "repo", 1);
  const auto file = write_text(dir / "a.json", synthetic_grid_text(1.0, 0.02, 1, shas[0].substr(0, 12)));
  { HistoryStore created = open_or_fail(db_path); }
  sqlite3* holder = nullptr;
  REQUIRE(sqlite3_open(db_path.c_str(), &holder) == SQLITE_OK);
  REQUIRE(sqlite3_exec(holder, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr) == SQLITE_OK);
  const CliRun r = run_cli_argv({"history", "record", file.string(), "--db", db_path, "--repo", (dir / "repo").string(),
                                 "--lock-timeout", "0.3"});
  sqlite3_exec(holder, "ROLLBACK", nullptr, nullptr, nullptr);
  sqlite3_close(holder);
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(line_count(r.err) == 1);
  CHECK(r.err.find("locked by another process") != std::string::npos);
  HistoryStore store = open_or_fail(db_path);
  CHECK(run_count(store) == 0);
  // Released, the same command lands.
  CHECK(run_cli_argv({"history", "record", file.string(), "--db", db_path, "--repo", (dir / "repo").string()}).exit_code == 0);
}

TEST_CASE("sqlite store: another program's database and a file that is none are refused untouched", "[history][store]") {
  const auto dir = history_scratch("sqlite_foreign");
  const std::string foreign = (dir / "app.sqlite").string();
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(foreign.c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, "CREATE TABLE users (name TEXT)", nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
  Result<HistoryStore> a = HistoryStore::open(foreign, StoreOptions{true, 1.0});
  REQUIRE_FALSE(a);
  CHECK(a.error().message.find("another program") != std::string::npos);
  REQUIRE(sqlite3_open(foreign.c_str(), &db) == SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  REQUIRE(sqlite3_prepare_v2(db, "SELECT count(*) FROM sqlite_master WHERE type = 'table'", -1, &st, nullptr) == SQLITE_OK);
  REQUIRE(sqlite3_step(st) == SQLITE_ROW);
  CHECK(sqlite3_column_int(st, 0) == 1);  // no table added
  sqlite3_finalize(st);
  sqlite3_close(db);

  const auto text = write_text(dir / "notes.sqlite", "these are my notes, not a database\n");
  Result<HistoryStore> b = HistoryStore::open(text.string(), StoreOptions{true, 1.0});
  REQUIRE_FALSE(b);
  CHECK(b.error().message.find("notes.sqlite") != std::string::npos);
  CHECK(slurp(text) == "these are my notes, not a database\n");

  Result<HistoryStore> missing = HistoryStore::open((dir / "none.sqlite").string(), StoreOptions{false, 1.0});
  REQUIRE_FALSE(missing);
  CHECK(missing.error().message.find("no history store here") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "none.sqlite"));
}

TEST_CASE("samples blobs hold doubles exactly and refuse what is not finite", "[history][store]") {
  const std::vector<double> v = {0.1, 1e-300, 3.0, -2.5, 123456789.123456789};
  Result<std::vector<double>> back = samples_from_blob(samples_blob(v));
  REQUIRE(back);
  CHECK(*back == v);
  CHECK_FALSE(samples_from_blob(std::string(7, '\0')));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(samples_from_blob(samples_blob({1.0, nan})));
}

TEST_CASE("an unreachable server is one line, exit 2, within the 5 s connect timeout", "[history][store]") {
  const auto start = std::chrono::steady_clock::now();
  // A closed port on this machine, and an address that never answers (routed nowhere, or dropped).
  for (const std::string url : {"postgresql://shatter@127.0.0.1:1/history", "postgresql://shatter@10.255.255.1:5432/history"}) {
    const CliRun r = run_cli_argv({"history", "show", "--db", url});
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find("cannot connect") != std::string::npos);
  }
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(12));
}
