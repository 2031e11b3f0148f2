#pragma once
// The store's contract, written once and run on every backend (SQLite in history_store_tests.cpp,
// PostgreSQL in history_postgres_tests.cpp): record and read back, re-record, migrate, refuse a newer
// schema, two recorders at once, a recorder killed at any moment, bad input that leaves the store as
// it was.

#include "harness/history/results_run.h"
#include "harness/history/store/history_schema.h"
#include "harness/history/store/history_store.h"
#include "harness/history/store/postgres_connection.h"
#include "harness/history/store/sqlite_connection.h"
#include "tests/support/cli_runner.h"
#include "tests/support/history_fixtures.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <string>
#include <thread>
#include <vector>

namespace shatter::test {

inline HistoryStore open_or_fail(const std::string& location) {
  Result<HistoryStore> s = HistoryStore::open(location, StoreOptions{true, 10.0});
  INFO((s ? std::string() : s.error().message));
  REQUIRE(s);
  return std::move(*s);
}

inline std::unique_ptr<SqlConnection> raw_connection(const std::string& location) {
  Result<std::unique_ptr<SqlConnection>> db =
      is_postgres_url(location) ? open_postgres(location) : open_sqlite(location, SqliteOpenOptions{true, 10.0});
  INFO((db ? std::string() : db.error().message));
  REQUIRE(db);
  return std::move(*db);
}

inline RunRecord synthetic_run(double scale, std::uint64_t seed, const std::string& sha, std::int64_t time,
                               int cells = 2) {
  Result<RunRecord> run = run_from_results_text(synthetic_grid_text(scale, 0.02, seed, sha.substr(0, 12), cells), "run.json");
  REQUIRE(run);
  run->commit = CommitInfo{sha, {}, "main", false, time};
  return std::move(*run);
}

inline std::int64_t run_count(HistoryStore& s) {
  Result<std::int64_t> n = s.run_count();
  REQUIRE(n);
  return *n;
}

inline std::int64_t measurement_count(HistoryStore& s) {
  Result<std::vector<SqlRow>> rows = s.connection().query("SELECT count(*) FROM sb_measurements");
  REQUIRE(rows);
  return sql_int(rows->front()[0]);
}

/// A run recorded reads back exactly: every series, every sample bit for bit; a second record of the
/// same run changes nothing.
inline void check_round_trip(const std::string& location) {
  HistoryStore store = open_or_fail(location);
  const RunRecord run = synthetic_run(1.0, 7, std::string(40, 'a'), 1000);
  Result<bool> added = store.record(run);
  REQUIRE(added);
  CHECK(*added);
  CHECK(run_count(store) == 1);
  Result<std::vector<SeriesInfo>> series = store.list_series({});
  REQUIRE(series);
  REQUIRE(series->size() == run.measurements.size());
  for (const Measurement& m : run.measurements) {
    Result<std::vector<SeriesRun>> runs = store.series_runs(series_id(m.series));
    REQUIRE(runs);
    REQUIRE(runs->size() == 1);
    CHECK(runs->front().commit == run.commit.sha);
    CHECK(runs->front().samples == m.samples);  // exact: the blob holds the doubles as they were
  }
  SeriesFilter only_stress;
  only_stress.what = "stage stress";
  only_stress.metric = "cpu_ms";
  Result<std::vector<SeriesInfo>> stress = store.list_series(only_stress);
  REQUIRE(stress);
  CHECK(stress->size() == 2);  // one per cell
  Result<bool> again = store.record(run);
  REQUIRE(again);
  CHECK_FALSE(*again);
  CHECK(run_count(store) == 1);
  CHECK(measurement_count(store) == static_cast<std::int64_t>(run.measurements.size()));
}

/// A store at schema version 1 (as the first binary wrote it: no acknowledgements, no generation,
/// branch per commit) is brought forward with its runs kept; a store newer than this binary is
/// refused with one line.
inline void check_migrations(const std::string& location) {
  {
    std::unique_ptr<SqlConnection> db = raw_connection(location);
    REQUIRE(migrate_history_schema(*db, 1));
    Result<int> v = history_schema_version(*db);
    REQUIRE(v);
    CHECK(*v == 1);
    // One run, written with version 1's columns.
    const std::string sha(40, 'b');
    REQUIRE(db->query("INSERT INTO sb_commits (sha, parents, branch, dirty, commit_time) VALUES (?, '', 'main', 0, 2000)", {sha}));
    REQUIRE(db->query("INSERT INTO sb_runs (id, commit_sha, kind, case_name, fingerprint, machine, source, context, "
                      "settings, passed, recorded_at) VALUES ('old-run', ?, 'grid', 'old', 'fp', 'm', 'old.json', '{}', "
                      "'{}', 1, '2026-01-01T00:00:00Z')",
                      {sha}));
    REQUIRE(db->query("INSERT INTO sb_series (id, kind, case_name, fingerprint, subject, what, metric, unit, better) "
                      "VALUES (7, 'grid', 'old', 'fp', 'cell', 'worst frame', 'cpu_ms', 'ms', 'lower')"));
    REQUIRE(db->query("INSERT INTO sb_measurements (run_id, series_id, median, samples) VALUES ('old-run', 7, 2.0, ?)",
                      {SqlBlob{samples_blob({1.0, 2.0, 3.0})}}));
    // Version 1 has no acknowledgements.
    HistoryStore old(std::move(db));
    CHECK_FALSE(old.acknowledge({7, sha, "n", {}}));
  }
  {
    HistoryStore store = open_or_fail(location);
    Result<int> v = history_schema_version(store.connection());
    REQUIRE(v);
    CHECK(*v == kHistorySchemaVersion);
    CHECK(run_count(store) == 1);
    Result<std::vector<SeriesRun>> runs = store.series_runs(7);
    REQUIRE(runs);
    REQUIRE(runs->size() == 1);
    CHECK(runs->front().samples == std::vector<double>{1.0, 2.0, 3.0});
    CHECK(runs->front().branch == "main");  // version 3 keeps the branch per run, taken from the commit
    CHECK(store.acknowledge({7, std::string(40, 'b'), "expected", {}}));
    Result<std::vector<Acknowledgement>> acks = store.acknowledgements(7);
    REQUIRE(acks);
    CHECK(acks->size() == 1);
    // New runs go in beside the old one.
    REQUIRE(store.record(synthetic_run(1.0, 1, std::string(40, 'c'), 3000)));
    CHECK(run_count(store) == 2);
    REQUIRE(store.connection().query("UPDATE sb_schema SET version = 99"));
  }
  Result<HistoryStore> newer = HistoryStore::open(location, StoreOptions{true, 1.0});
  REQUIRE_FALSE(newer);
  CHECK(newer.error().message.find("schema version 99, newer than this shatterbench") != std::string::npos);
  CHECK(newer.error().message.find('\n') == std::string::npos);
}

/// Two recorders at once (two CI shards) both land; two recorders of one file land it once.
inline void check_concurrent_recorders(const std::string& location, const std::filesystem::path& dir) {
  const std::vector<std::string> shas = make_commits(dir / "repo", 2);
  const auto a = write_text(dir / "a.json", synthetic_grid_text(1.0, 0.02, 1, shas[1].substr(0, 12), 40));
  const auto b = write_text(dir / "b.json", synthetic_grid_text(1.1, 0.02, 2, shas[1].substr(0, 12), 40));
  std::vector<pid_t> pids;
  int k = 0;
  for (const auto& file : {a, b, a, b}) {
    const std::string tag = std::to_string(k++);
    pids.push_back(spawn_cli({"history", "record", file.string(), "--db", location, "--repo", (dir / "repo").string()}, {},
                             dir / ("out" + tag), dir / ("err" + tag)));
  }
  for (std::size_t i = 0; i < pids.size(); ++i) {
    REQUIRE(pids[i] > 0);
    int status = 0;
    ::waitpid(pids[i], &status, 0);
    INFO(slurp(dir / ("err" + std::to_string(i))));
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  }
  HistoryStore store = open_or_fail(location);
  CHECK(run_count(store) == 2);
  Result<RunRecord> ra = read_results_run(a), rb = read_results_run(b);
  REQUIRE(ra);
  REQUIRE(rb);
  CHECK(measurement_count(store) == static_cast<std::int64_t>(ra->measurements.size() + rb->measurements.size()));
}

/// A recorder killed with SIGKILL at any moment leaves the store as it was or with the whole run.
inline void check_killed_recorder(const std::string& location, const std::filesystem::path& dir) {
  const std::vector<std::string> shas = make_commits(dir / "repo", 1);
  Result<RunRecord> whole = run_from_results_text(synthetic_grid_text(1.0, 0.02, 3, shas[0].substr(0, 12), 600), "big.json");
  REQUIRE(whole);
  const auto big = write_text(dir / "big.json", synthetic_grid_text(1.0, 0.02, 3, shas[0].substr(0, 12), 600));
  int landed = 0, cut = 0;
  // Kills every 15 ms into the run at first, then later and later until one recorder finishes.
  for (int delay_ms = 0; delay_ms <= 20000 && landed == 0; delay_ms += delay_ms < 300 ? 15 : delay_ms / 2) {
    const pid_t pid = spawn_cli({"history", "record", big.string(), "--db", location, "--repo", (dir / "repo").string()}, {},
                                dir / "out", dir / "err");
    REQUIRE(pid > 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    HistoryStore store = open_or_fail(location);
    const std::int64_t runs = run_count(store);
    const std::int64_t measurements = measurement_count(store);
    INFO("killed after " << delay_ms << " ms");
    REQUIRE(runs <= 1);
    CHECK(measurements == (runs == 1 ? static_cast<std::int64_t>(whole->measurements.size()) : 0));
    landed += static_cast<int>(runs);
    cut += WIFSIGNALED(status) ? 1 : 0;
  }
  CHECK(cut > 0);     // some recorder was killed before it ended
  CHECK(landed == 1); // and a later one landed the whole run
}

/// Bad input: one line on stderr, exit 2, the store as it was.
inline void check_bad_input_leaves_store(const std::string& location, const std::filesystem::path& dir) {
  const std::vector<std::string> shas = make_commits(dir / "repo", 1);
  const auto good = write_text(dir / "good.json", synthetic_grid_text(1.0, 0.02, 4, shas[0].substr(0, 12)));
  const std::string repo = (dir / "repo").string();
  REQUIRE(run_cli_argv({"history", "record", good.string(), "--db", location, "--repo", repo}).exit_code == 0);
  std::string cut_text = synthetic_grid_text(1.2, 0.02, 5, shas[0].substr(0, 12));
  cut_text.resize(cut_text.size() / 2);
  const auto truncated = write_text(dir / "truncated.json", cut_text);
  const auto gbench = write_text(dir / "gbench.json", R"({"context": {"date": "x"}, "benchmarks": []})");
  const auto other = write_text(dir / "other.json", synthetic_grid_text(1.3, 0.02, 6, "0000000000ff"));
  const auto fine = write_text(dir / "fine.json", synthetic_grid_text(1.4, 0.02, 7, shas[0].substr(0, 12)));
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{truncated.string()}, "truncated.json"},
      {{gbench.string()}, "not a shatterbench results file"},
      {{other.string()}, "not a commit of the repository"},
      {{fine.string(), truncated.string()}, "truncated.json"},  // the good one is not recorded either
      {{fine.string(), "--commit", "no-such-branch"}, "no-such-branch"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"history", "record"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.insert(args.end(), {"--db", location, "--repo", repo});
    const CliRun r = run_cli_argv(args);
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(c.says) != std::string::npos);
  }
  HistoryStore store = open_or_fail(location);
  CHECK(run_count(store) == 1);
}

}  // namespace shatter::test
