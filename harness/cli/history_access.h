#pragma once
/// What the `history` commands and the `--record` flags of grid, accuracy and table share: the store's
/// location flags, opening it, naming commits, and recording results.

#include "harness/history/store/history_store.h"

#include <CLI/CLI.hpp>

#include <ostream>
#include <cstdint>
#include <string>
#include <vector>

namespace shatter::cli {

/// Where the store is and how long to wait for its lock.
struct StoreFlags {
  std::string db;               ///< --db (else SHATTERBENCH_DB, else results/history.sqlite)
  double lock_timeout_s = 10.0; ///< --lock-timeout
};

/// Adds --db and --lock-timeout to `cmd`.
void add_store_flags(CLI::App* cmd, StoreFlags& flags);

/// Opens the store of `flags` (creating an SQLite file when `create`).
Result<HistoryStore> open_store(const StoreFlags& flags, bool create);

/// Adds the series filters (--case, --kind, --subject, --what, --metric, --fingerprint) to `cmd`.
void add_series_filter_flags(CLI::App* cmd, SeriesFilter& filter);

/// How recorded runs are tied to their commit.
struct CommitFlags {
  std::string commit;  ///< --commit REV (default: each results file's own `context.commit`)
  std::string repo;    ///< --repo DIR, the git repository that knows the commit (default: .)
  std::string branch;  ///< --branch NAME (default: git's, or the CI's)
};

/// Adds --commit, --repo and --branch to `cmd`.
void add_commit_flags(CLI::App* cmd, CommitFlags& flags);

/// A results file's text with the name it came from.
struct ResultsText {
  std::string text;
  std::string source;
};

/// Records each of `results` at its commit into the store of `store`, printing one line per run on
/// `report` ("recorded ..." or "already recorded ..."). Every file is read and its commit resolved
/// before anything is written, so a bad file leaves the store unchanged. Exit code: 0, or 2 with one
/// line on stderr.
int record_results(const std::vector<ResultsText>& results, const StoreFlags& store, const CommitFlags& commit,
                   std::ostream& report);

/// `--record` of grid, accuracy and table: the run goes into the store at the commit the binary was
/// built from (its context.commit, which git in the working folder must know).
struct RecordFlags {
  bool record = false;
  StoreFlags store;
};

/// Adds --record and --db to `cmd`.
void add_record_flags(CLI::App* cmd, RecordFlags& flags);

/// Before a run: with --record, the store opens and git knows this binary's commit, so that a run of
/// an hour does not end in an error it could have given at once.
Status check_record_target(const RecordFlags& flags);

/// After a run: records `text` (the run's results JSON) when --record is given, its line on stderr
/// (stdout is the command's table); an exit code.
int record_if_asked(const RecordFlags& flags, const std::string& text, const std::string& source);

/// The commit `revision` names: a sha prefix recorded in `store`, else what git at `repo` says (and
/// is then required to be recorded). Error names the revision.
Result<CommitInfo> recorded_commit(HistoryStore& store, const std::string& revision, const std::string& repo);

/// The commit time `--since REV` starts at (recorded_commit; the error prefixed "--since: "), or the
/// earliest time when `revision` is empty: every commit.
Result<std::int64_t> since_time(HistoryStore& store, const std::string& revision, const std::string& repo);

/// A series in one line for tables: "building · 100 x 25 voronoi/... · stage physics · cpu_ms".
std::string series_label(const SeriesKey& key);

}  // namespace shatter::cli
