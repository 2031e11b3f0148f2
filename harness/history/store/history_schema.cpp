#include "harness/history/store/history_schema.h"

#include <fmt/core.h>

#include <string>
#include <vector>

namespace shatter {
namespace {

/// One migration: the statements that bring version - 1 to version. `{blob}` is the blob type.
struct Migration {
  int version;
  std::vector<const char*> statements;
};

const std::vector<Migration>& migrations() {
  static const std::vector<Migration> all = {
      {1,
       {"CREATE TABLE sb_commits (sha TEXT PRIMARY KEY, parents TEXT NOT NULL, branch TEXT NOT NULL, "
        "dirty BIGINT NOT NULL, commit_time BIGINT NOT NULL)",
        "CREATE TABLE sb_runs (id TEXT PRIMARY KEY, commit_sha TEXT NOT NULL REFERENCES sb_commits(sha), "
        "kind TEXT NOT NULL, case_name TEXT NOT NULL, fingerprint TEXT NOT NULL, machine TEXT NOT NULL, "
        "source TEXT NOT NULL, context TEXT NOT NULL, settings TEXT NOT NULL, passed BIGINT NOT NULL, "
        "recorded_at TEXT NOT NULL)",
        "CREATE INDEX sb_runs_commit ON sb_runs(commit_sha)",
        "CREATE TABLE sb_series (id BIGINT PRIMARY KEY, kind TEXT NOT NULL, case_name TEXT NOT NULL, "
        "fingerprint TEXT NOT NULL, subject TEXT NOT NULL, what TEXT NOT NULL, metric TEXT NOT NULL, "
        "unit TEXT NOT NULL, better TEXT NOT NULL)",
        "CREATE TABLE sb_measurements (run_id TEXT NOT NULL REFERENCES sb_runs(id), "
        "series_id BIGINT NOT NULL REFERENCES sb_series(id), median DOUBLE PRECISION NOT NULL, "
        "samples {blob} NOT NULL, PRIMARY KEY (run_id, series_id))",
        "CREATE INDEX sb_measurements_series ON sb_measurements(series_id)"}},
      {2,
       {"CREATE TABLE sb_acknowledgements (series_id BIGINT NOT NULL REFERENCES sb_series(id), "
        "commit_sha TEXT NOT NULL REFERENCES sb_commits(sha), note TEXT NOT NULL, created_at TEXT NOT NULL, "
        "PRIMARY KEY (series_id, commit_sha))"}},
      // Commits of one second ordered by ancestry; branch and dirty flag per run (a commit is
      // recorded from several branches and trees).
      {3,
       {"ALTER TABLE sb_commits ADD COLUMN generation BIGINT NOT NULL DEFAULT 0",
        "ALTER TABLE sb_runs ADD COLUMN branch TEXT NOT NULL DEFAULT ''",
        "ALTER TABLE sb_runs ADD COLUMN dirty BIGINT NOT NULL DEFAULT 0",
        "UPDATE sb_runs SET branch = (SELECT c.branch FROM sb_commits c WHERE c.sha = sb_runs.commit_sha), "
        "dirty = (SELECT c.dirty FROM sb_commits c WHERE c.sha = sb_runs.commit_sha)"}},
  };
  return all;
}

Result<bool> table_exists(SqlConnection& db, const char* table) {
  const char* sql = db.dialect() == "sqlite"
                        ? "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?"
                        : "SELECT 1 FROM information_schema.tables WHERE table_schema = current_schema() AND table_name = ?";
  Result<std::vector<SqlRow>> rows = db.query(sql, {std::string(table)});
  if (!rows) return rows.error();
  return !rows->empty();
}

/// A file holding other tables and no store is another program's database: never written to.
Status refuse_foreign_sqlite(SqlConnection& db) {
  if (db.dialect() != "sqlite") return {};
  Result<std::vector<SqlRow>> rows = db.query("SELECT count(*) FROM sqlite_master WHERE type = 'table'", {});
  if (!rows) return rows.error();
  if (sql_int(rows->front()[0]) > 0)
    return Error{db.name() + ": an SQLite database of another program (it has tables but no shatterbench history)"};
  return {};
}

}  // namespace

Result<int> history_schema_version(SqlConnection& db) {
  Result<bool> exists = table_exists(db, "sb_schema");
  if (!exists) return exists.error();
  if (!*exists) return 0;
  Result<std::vector<SqlRow>> rows = db.query("SELECT max(version) FROM sb_schema", {});
  if (!rows) return rows.error();
  return rows->empty() ? 0 : static_cast<int>(sql_int(rows->front()[0]));
}

Status migrate_history_schema(SqlConnection& db, int target) {
  // A store at the target needs no write lock: read-only commands on a busy store do not queue.
  Result<int> seen = history_schema_version(db);
  if (!seen) return seen.error();
  if (*seen > kHistorySchemaVersion)
    return Error{fmt::format("{}: the store has schema version {}, newer than this shatterbench reads ({}); "
                             "use a newer shatterbench",
                             db.name(), *seen, kHistorySchemaVersion)};
  if (*seen >= target) return {};

  WriteTransaction tx(db);
  if (!tx.started()) return tx.started().error();
  if (Status s = db.lock_schema(); !s) return s;
  Result<int> version = history_schema_version(db);  // another process may have migrated meanwhile
  if (!version) return version.error();
  if (*version >= target) return {};
  if (*version == 0) {
    if (Status s = refuse_foreign_sqlite(db); !s) return s;
    Result<std::vector<SqlRow>> made = db.query("CREATE TABLE sb_schema (version BIGINT NOT NULL)", {});
    if (!made) return made.error();
  }
  for (const Migration& m : migrations()) {
    if (m.version <= *version || m.version > target) continue;
    for (const char* statement : m.statements) {
      std::string sql = statement;
      if (const std::size_t at = sql.find("{blob}"); at != std::string::npos) sql.replace(at, 6, db.blob_type());
      Result<std::vector<SqlRow>> done = db.query(sql, {});
      if (!done) return done.error();
    }
  }
  Result<std::vector<SqlRow>> cleared = db.query("DELETE FROM sb_schema", {});
  if (!cleared) return cleared.error();
  Result<std::vector<SqlRow>> set = db.query("INSERT INTO sb_schema (version) VALUES (?)", {std::int64_t{target}});
  if (!set) return set.error();
  return tx.commit();
}

}  // namespace shatter
