#pragma once
/// The history store (docs/history.md): runs recorded at commits, read back per series. The queries
/// that the terminal views, the gate and the HTML dashboard need are here, each a function of the
/// store: the list of series, one series with every sample, acknowledgements.
///
/// Integrity: a run is written in one transaction (kill -9 at any moment leaves the store as it was
/// or with the whole run); a run's id is a hash of its results file, so recording a file twice does
/// nothing the second time, also when two processes race to record it.

#include "harness/history/store/history_model.h"
#include "harness/history/store/sql_connection.h"

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// The store used when neither `--db` nor SHATTERBENCH_DB names one.
inline constexpr const char* kDefaultHistoryStore = "results/history.sqlite";

/// The store's location: `flag` when given, else SHATTERBENCH_DB when set, else kDefaultHistoryStore.
std::string history_store_location(const std::string& flag);

/// How a store is opened.
struct StoreOptions {
  bool create = false;           ///< an SQLite file that does not exist is created (commands that write)
  double lock_timeout_s = 10.0;  ///< longest wait for another writer's lock (SQLite), s
};

/// Which series a query returns: empty fields match every series; `what` and `subject` match when
/// they contain the text, the others when equal.
struct SeriesFilter {
  std::string kind;
  std::string case_name;
  std::string subject;
  std::string what;
  std::string metric;
  std::string fingerprint;
};

/// A store, open.
class HistoryStore {
 public:
  /// Opens the store at `location` (a path, or a postgresql:// URL) and brings its schema forward.
  static Result<HistoryStore> open(const std::string& location, const StoreOptions& options);
  /// Wraps an open connection whose schema is current.
  explicit HistoryStore(std::unique_ptr<SqlConnection> db) : db_(std::move(db)) {}

  /// The store's name as errors show it.
  [[nodiscard]] const std::string& name() const { return db_->name(); }
  /// The connection (tests; the schema's migration).
  SqlConnection& connection() { return *db_; }

  /// Records `run` whole, in one transaction. False when a run of its id is already there.
  Result<bool> record(const RunRecord& run);
  /// Records every run of `runs` in one transaction (all or none); per run, false when it was
  /// already there.
  Result<std::vector<bool>> record_all(const std::vector<RunRecord>& runs);
  /// True when a run of `id` is recorded.
  Result<bool> has_run(const std::string& id);
  /// How many runs the store holds.
  Result<std::int64_t> run_count();

  /// The series that match `filter`, ordered by kind, case, subject, what and metric.
  Result<std::vector<SeriesInfo>> list_series(const SeriesFilter& filter);
  /// Every run's measurement of `series`, in commit order (committer time, then sha), from commits at
  /// or after `since_time`.
  Result<std::vector<SeriesRun>> series_runs(std::int64_t series,
                                             std::int64_t since_time = std::numeric_limits<std::int64_t>::min());
  /// Hands every series of `filter`, in the order of list_series, to `visit` with its runs in commit
  /// order from commits at or after `since_time`; a series is held only while it is visited. Reads a
  /// few recent runs run by run (the primary key), and a long history series by series (the index).
  Status visit_series_runs(const SeriesFilter& filter, std::int64_t since_time,
                           const std::function<Status(const SeriesInfo&, std::vector<SeriesRun>&)>& visit);
  /// Every series of `filter` with its runs (visit_series_runs, collected).
  Result<std::vector<std::pair<SeriesInfo, std::vector<SeriesRun>>>> filtered_series_runs(
      const SeriesFilter& filter, std::int64_t since_time = std::numeric_limits<std::int64_t>::min());

  /// The recorded commit whose sha starts with `prefix` (at least 4 hex digits); none when no
  /// recorded commit matches; an error when several do.
  Result<std::optional<CommitInfo>> find_commit(const std::string& prefix);

  /// The runs recorded at commit `sha`, in the order they were recorded.
  Result<std::vector<RunSummary>> runs_at(const std::string& sha);
  /// The committer time of the `back`-th newest commit (0: the newest) that has a run of `case_name`
  /// (any case when empty); none when there are fewer commits.
  Result<std::optional<std::int64_t>> recent_commit_time(const std::string& case_name, int back);

  /// Marks `ack.series_id`'s change at `ack.commit` as expected (the commit must be recorded).
  Status acknowledge(const Acknowledgement& ack);
  /// The acknowledgements of `series`, latest commit last.
  Result<std::vector<Acknowledgement>> acknowledgements(std::int64_t series);
  /// Every acknowledgement of the store, by series, latest commit last in each.
  Result<std::vector<Acknowledgement>> all_acknowledgements();

 private:
  /// Writes `run` inside the open transaction; false when its id is already there.
  Result<bool> insert_run(const RunRecord& run);

  std::unique_ptr<SqlConnection> db_;
};

/// Samples as a blob (little-endian IEEE doubles) and back.
std::string samples_blob(const std::vector<double>& samples);
/// Error when the blob's size is not a multiple of 8 or a value is not finite.
Result<std::vector<double>> samples_from_blob(const std::string& blob);

}  // namespace shatter
