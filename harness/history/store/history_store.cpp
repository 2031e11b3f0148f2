#include "harness/history/store/history_store.h"

#include "harness/history/store/history_schema.h"
#include "harness/history/store/postgres_connection.h"
#include "harness/history/store/sqlite_connection.h"
#include "harness/results/fnv1a.h"
#include "harness/results/sample_statistics.h"

#include <fmt/chrono.h>
#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

namespace shatter {
namespace {

static_assert(std::endian::native == std::endian::little, "samples are stored as little-endian doubles");

std::string now_utc() {
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())));
}

std::string join(const std::vector<std::string>& parts, char separator) {
  std::string out;
  for (const std::string& p : parts) {
    if (!out.empty()) out += separator;
    out += p;
  }
  return out;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (from < text.size()) {
    const std::size_t to = std::min(text.find(separator, from), text.size());
    out.push_back(text.substr(from, to - from));
    from = to + 1;
  }
  return out;
}

Better better_from(const std::string& name) {
  return name == "higher" ? Better::higher : name == "none" ? Better::none : Better::lower;
}

/// Runs `sql` for `rows` rows of `width` values each, as few multi-row INSERTs as the backend's
/// parameter limit allows.
Status insert_rows(SqlConnection& db, const std::string& head, const std::string& tail, std::size_t width,
                   const std::vector<SqlValue>& values) {
  const std::size_t rows = values.size() / width;
  const std::size_t per_statement = std::max<std::size_t>(1, std::min<std::size_t>(500, db.max_parameters() / width));
  std::string group = "(";
  for (std::size_t i = 0; i < width; ++i) group += i ? ", ?" : "?";
  group += ")";
  for (std::size_t first = 0; first < rows; first += per_statement) {
    const std::size_t n = std::min(per_statement, rows - first);
    std::string sql = head;
    for (std::size_t i = 0; i < n; ++i) sql += (i ? ", " : " ") + group;
    sql += tail;
    std::vector<SqlValue> params(values.begin() + static_cast<std::ptrdiff_t>(first * width),
                                 values.begin() + static_cast<std::ptrdiff_t>((first + n) * width));
    Result<std::vector<SqlRow>> done = db.query(sql, params);
    if (!done) return done.error();
  }
  return {};
}

constexpr const char* kSeriesColumns = "id, kind, case_name, fingerprint, subject, what, metric, unit, better";

SeriesInfo series_from_row(const SqlRow& r) {
  SeriesInfo s;
  s.id = sql_int(r[0]);
  s.key = SeriesKey{sql_text(r[1]), sql_text(r[2]), sql_text(r[3]), sql_text(r[4]), sql_text(r[5]),
                    sql_text(r[6]), sql_text(r[7]), better_from(sql_text(r[8]))};
  return s;
}

/// The WHERE clause of `filter` over the series table aliased `s`, and its parameters.
std::string series_where(const SqlConnection& db, const SeriesFilter& filter, std::vector<SqlValue>& params) {
  std::string where = "1 = 1";
  auto equal = [&](const char* column, const std::string& value) {
    if (value.empty()) return;
    where += fmt::format(" AND s.{} = ?", column);
    params.emplace_back(value);
  };
  // Substring match without LIKE's wildcards: the user's text is data, `%` and `_` included.
  auto contains = [&](const char* column, const std::string& value) {
    if (value.empty()) return;
    where += fmt::format(fmt::runtime(db.dialect() == "sqlite" ? " AND instr(s.{}, ?) > 0" : " AND strpos(s.{}, ?) > 0"),
                         column);
    params.emplace_back(value);
  };
  equal("kind", filter.kind);
  equal("case_name", filter.case_name);
  equal("metric", filter.metric);
  equal("fingerprint", filter.fingerprint);
  contains("subject", filter.subject);
  contains("what", filter.what);
  return where;
}

}  // namespace

const char* better_name(Better b) {
  switch (b) {
    case Better::lower: return "lower";
    case Better::higher: return "higher";
    case Better::none: return "none";
  }
  return "none";
}

std::int64_t series_id(const SeriesKey& key) {
  std::uint64_t h = kFnv1aBasis;
  for (const std::string* field : {&key.kind, &key.case_name, &key.fingerprint, &key.subject, &key.what, &key.metric})
    h = fnv1a_field(*field, h);
  return static_cast<std::int64_t>(h);
}

std::string history_store_location(const std::string& flag) {
  if (!flag.empty()) return flag;
  if (const char* env = std::getenv("SHATTERBENCH_DB"); env != nullptr && *env != '\0') return env;
  return kDefaultHistoryStore;
}

std::string samples_blob(const std::vector<double>& samples) {
  std::string blob(samples.size() * sizeof(double), '\0');
  if (!samples.empty()) std::memcpy(blob.data(), samples.data(), blob.size());
  return blob;
}

Result<std::vector<double>> samples_from_blob(const std::string& blob) {
  if (blob.size() % sizeof(double) != 0) return Error{fmt::format("a samples blob of {} bytes", blob.size())};
  std::vector<double> samples(blob.size() / sizeof(double));
  if (!samples.empty()) std::memcpy(samples.data(), blob.data(), blob.size());
  for (double v : samples)
    if (!std::isfinite(v)) return Error{"a samples blob holds a value that is not finite"};
  return samples;
}

Result<HistoryStore> HistoryStore::open(const std::string& location, const StoreOptions& options) {
  Result<std::unique_ptr<SqlConnection>> db =
      is_postgres_url(location) ? open_postgres(location)
                                : open_sqlite(location, SqliteOpenOptions{options.create, options.lock_timeout_s});
  if (!db) return db.error();
  // Commands that only read never make a store: an empty file or database is not one.
  if (!options.create) {
    Result<int> version = history_schema_version(**db);
    if (!version) return version.error();
    if (*version == 0) return Error{(*db)->name() + ": no history store here (record a run first: shatterbench history record)"};
  }
  if (Status s = migrate_history_schema(**db); !s) return s.error();
  return HistoryStore(std::move(*db));
}

Result<bool> HistoryStore::has_run(const std::string& id) {
  Result<std::vector<SqlRow>> rows = db_->query("SELECT 1 FROM sb_runs WHERE id = ?", {id});
  if (!rows) return rows.error();
  return !rows->empty();
}

Result<std::int64_t> HistoryStore::run_count() {
  Result<std::vector<SqlRow>> rows = db_->query("SELECT count(*) FROM sb_runs", {});
  if (!rows) return rows.error();
  return sql_int(rows->front()[0]);
}

Result<bool> HistoryStore::record(const RunRecord& run) {
  Result<std::vector<bool>> added = record_all({run});
  if (!added) return added.error();
  return static_cast<bool>(added->front());
}

Result<std::vector<bool>> HistoryStore::record_all(const std::vector<RunRecord>& runs) {
  WriteTransaction tx(*db_);
  if (!tx.started()) return tx.started().error();
  std::vector<bool> added;
  for (const RunRecord& run : runs) {
    Result<bool> one = insert_run(run);
    if (!one) return one.error();  // the transaction rolls back: none of the runs is recorded
    added.push_back(*one);
  }
  if (Status s = tx.commit(); !s) return s.error();
  return added;
}

Result<bool> HistoryStore::insert_run(const RunRecord& run) {
  const CommitInfo& c = run.commit;
  Result<std::vector<SqlRow>> commit = db_->query(
      "INSERT INTO sb_commits (sha, parents, branch, dirty, commit_time, generation) VALUES (?, ?, ?, ?, ?, ?) "
      "ON CONFLICT (sha) DO NOTHING",
      {c.sha, join(c.parents, ' '), c.branch, std::int64_t{c.dirty ? 1 : 0}, c.time, c.generation});
  if (!commit) return commit.error();
  // The run's row decides: a second recorder of the same file (or a race of two) inserts nothing.
  Result<std::vector<SqlRow>> inserted = db_->query(
      "INSERT INTO sb_runs (id, commit_sha, kind, case_name, fingerprint, machine, source, context, settings, "
      "passed, recorded_at, branch, dirty) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (id) DO NOTHING "
      "RETURNING id",
      {run.id, c.sha, run.kind, run.case_name, run.fingerprint, run.machine, run.source, run.context_json,
       run.settings_json, std::int64_t{run.passed ? 1 : 0}, now_utc(), c.branch, std::int64_t{c.dirty ? 1 : 0}});
  if (!inserted) return inserted.error();
  if (inserted->empty()) return false;  // already recorded: nothing more of it is written

  std::vector<SqlValue> series, measurements;
  series.reserve(run.measurements.size() * 9);
  measurements.reserve(run.measurements.size() * 4);
  std::unordered_map<std::int64_t, const SeriesKey*> seen;
  for (const Measurement& m : run.measurements) {
    const SeriesKey& k = m.series;
    const std::int64_t id = series_id(k);
    if (!seen.emplace(id, &k).second)
      return Error{fmt::format("{}: the run measures {} {} {} twice", name(), k.subject, k.what, k.metric)};
    series.insert(series.end(), {id, k.kind, k.case_name, k.fingerprint, k.subject, k.what, k.metric, k.unit,
                                 std::string(better_name(k.better))});
    measurements.insert(measurements.end(), {run.id, id, median_of(m.samples), SqlBlob{samples_blob(m.samples)}});
  }
  if (Status s = insert_rows(*db_, fmt::format("INSERT INTO sb_series ({}) VALUES", kSeriesColumns),
                             " ON CONFLICT (id) DO NOTHING", 9, series);
      !s)
    return s.error();
  if (Status s = insert_rows(*db_, "INSERT INTO sb_measurements (run_id, series_id, median, samples) VALUES", "", 4,
                             measurements);
      !s)
    return s.error();
  return true;
}

Result<std::vector<SeriesInfo>> HistoryStore::list_series(const SeriesFilter& filter) {
  std::vector<SqlValue> params;
  const std::string sql = fmt::format("SELECT {} FROM sb_series s WHERE {} ORDER BY {}",
                                      "s.id, s.kind, s.case_name, s.fingerprint, s.subject, s.what, s.metric, s.unit, s.better",
                                      series_where(*db_, filter, params),
                                      // Byte order on both backends, whatever the server's collation.
                                      db_->dialect() == "sqlite" ? "kind, case_name, subject, what, metric, id"
                                                                 : "kind COLLATE \"C\", case_name COLLATE \"C\", subject COLLATE "
                                                                   "\"C\", what COLLATE \"C\", metric COLLATE \"C\", id");
  std::vector<SeriesInfo> out;
  Status s = db_->for_each_row(sql, params, [&out](const SqlRow& r) {
    out.push_back(series_from_row(r));
    return Status{};
  });
  if (!s) return s.error();
  return out;
}

Result<std::vector<SeriesRun>> HistoryStore::series_runs(std::int64_t series, std::int64_t since_time) {
  std::vector<SeriesRun> out;
  Status s = db_->for_each_row(
      "SELECT m.run_id, r.commit_sha, c.commit_time, r.branch, r.passed, m.samples, c.generation, r.dirty "
      "FROM sb_measurements m JOIN sb_runs r ON r.id = m.run_id JOIN sb_commits c ON c.sha = r.commit_sha "
      "WHERE m.series_id = ? AND c.commit_time >= ? ORDER BY c.commit_time, c.generation, c.sha, r.recorded_at, m.run_id",
      {series, since_time}, [&](const SqlRow& r) -> Status {
        Result<std::vector<double>> samples = samples_from_blob(sql_blob(r[5]));
        if (!samples) return Error{fmt::format("{}: run {}: {}", name(), sql_text(r[0]), samples.error().message)};
        out.push_back(SeriesRun{sql_text(r[0]), sql_text(r[1]), sql_int(r[2]), sql_text(r[3]), sql_int(r[4]) != 0,
                                std::move(*samples), sql_int(r[6]), sql_int(r[7]) != 0});
        return {};
      });
  if (!s) return s.error();
  return out;
}

Status HistoryStore::visit_series_runs(const SeriesFilter& filter, std::int64_t since_time,
                                       const std::function<Status(const SeriesInfo&, std::vector<SeriesRun>&)>& visit) {
  Result<std::vector<SeriesInfo>> list = list_series(filter);
  if (!list) return list.error();
  if (list->empty()) return {};
  // The runs in range, in commit order; a measurement is placed by its run's position.
  struct RunOrder {
    std::string commit;
    std::int64_t time;
    std::string branch;
    bool passed;
    std::int64_t generation;
    bool dirty;
  };
  std::vector<std::string> run_ids;
  std::vector<RunOrder> runs;
  std::unordered_map<std::string, std::size_t> position;
  Status listed = db_->for_each_row(
      "SELECT r.id, r.commit_sha, c.commit_time, r.branch, r.passed, c.generation, r.dirty FROM sb_runs r "
      "JOIN sb_commits c ON c.sha = r.commit_sha WHERE c.commit_time >= ? "
      "ORDER BY c.commit_time, c.generation, c.sha, r.recorded_at, r.id",
      {since_time}, [&](const SqlRow& r) {
        position.emplace(sql_text(r[0]), runs.size());
        run_ids.push_back(sql_text(r[0]));
        runs.push_back({sql_text(r[1]), sql_int(r[2]), sql_text(r[3]), sql_int(r[4]) != 0, sql_int(r[5]), sql_int(r[6]) != 0});
        return Status{};
      });
  if (!listed) return listed;
  Result<std::int64_t> total = run_count();
  if (!total) return total.error();

  auto make_run = [&](std::size_t at, const std::string& blob) -> Result<SeriesRun> {
    Result<std::vector<double>> samples = samples_from_blob(blob);
    if (!samples) return Error{fmt::format("{}: run {}: {}", name(), run_ids[at], samples.error().message)};
    const RunOrder& o = runs[at];
    return SeriesRun{run_ids[at], o.commit, o.time, o.branch, o.passed, std::move(*samples), o.generation, o.dirty};
  };
  if (runs.size() * 4 <= static_cast<std::size_t>(*total)) {
    // A recent window: every measurement of each run in range, by the primary key.
    std::unordered_map<std::int64_t, std::size_t> index_of;
    for (std::size_t i = 0; i < list->size(); ++i) index_of.emplace((*list)[i].id, i);
    std::vector<std::vector<SeriesRun>> per_series(list->size());
    for (std::size_t at = 0; at < runs.size(); ++at) {
      Status s = db_->for_each_row("SELECT series_id, samples FROM sb_measurements WHERE run_id = ?", {run_ids[at]},
                                   [&](const SqlRow& r) -> Status {
                                     const auto found = index_of.find(sql_int(r[0]));
                                     if (found == index_of.end()) return {};
                                     Result<SeriesRun> run = make_run(at, sql_blob(r[1]));
                                     if (!run) return run.error();
                                     per_series[found->second].push_back(std::move(*run));
                                     return {};
                                   });
      if (!s) return s;
    }
    for (std::size_t i = 0; i < list->size(); ++i)
      if (Status s = visit((*list)[i], per_series[i]); !s) return s;
    return {};
  }
  // A long history: each series' measurements by the series index, placed in commit order.
  for (const SeriesInfo& info : *list) {
    std::vector<std::pair<std::size_t, SeriesRun>> placed;
    Status s = db_->for_each_row("SELECT run_id, samples FROM sb_measurements WHERE series_id = ?", {info.id},
                                 [&](const SqlRow& r) -> Status {
                                   const auto found = position.find(sql_text(r[0]));
                                   if (found == position.end()) return {};  // before since_time
                                   Result<SeriesRun> run = make_run(found->second, sql_blob(r[1]));
                                   if (!run) return run.error();
                                   placed.emplace_back(found->second, std::move(*run));
                                   return {};
                                 });
    if (!s) return s;
    std::sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<SeriesRun> ordered;
    ordered.reserve(placed.size());
    for (auto& p : placed) ordered.push_back(std::move(p.second));
    if (Status v = visit(info, ordered); !v) return v;
  }
  return {};
}

Result<std::vector<std::pair<SeriesInfo, std::vector<SeriesRun>>>> HistoryStore::filtered_series_runs(
    const SeriesFilter& filter, std::int64_t since_time) {
  std::vector<std::pair<SeriesInfo, std::vector<SeriesRun>>> out;
  Status s = visit_series_runs(filter, since_time, [&out](const SeriesInfo& info, std::vector<SeriesRun>& runs) {
    out.emplace_back(info, std::move(runs));
    return Status{};
  });
  if (!s) return s.error();
  return out;
}

Result<std::optional<CommitInfo>> HistoryStore::find_commit(const std::string& prefix) {
  if (prefix.size() < 4 || prefix.size() > 40 ||
      !std::all_of(prefix.begin(), prefix.end(), [](char ch) { return std::isxdigit(static_cast<unsigned char>(ch)); }))
    return std::optional<CommitInfo>{};
  std::string lower = prefix;
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  Result<std::vector<SqlRow>> rows = db_->query(
      "SELECT sha, parents, branch, dirty, commit_time, generation FROM sb_commits WHERE sha LIKE ? LIMIT 2",
      {lower + "%"});
  if (!rows) return rows.error();
  if (rows->empty()) return std::optional<CommitInfo>{};
  if (rows->size() > 1) return Error{fmt::format("{}: commit {} is ambiguous: give more digits", name(), prefix)};
  const SqlRow& r = rows->front();
  return std::optional<CommitInfo>{
      CommitInfo{sql_text(r[0]), split(sql_text(r[1]), ' '), sql_text(r[2]), sql_int(r[3]) != 0, sql_int(r[4]), sql_int(r[5])}};
}

Result<std::vector<RunSummary>> HistoryStore::runs_at(const std::string& sha) {
  Result<std::vector<SqlRow>> rows = db_->query(
      "SELECT id, source, kind, case_name, passed FROM sb_runs WHERE commit_sha = ? ORDER BY recorded_at, id", {sha});
  if (!rows) return rows.error();
  std::vector<RunSummary> out;
  for (const SqlRow& r : *rows)
    out.push_back({sql_text(r[0]), sql_text(r[1]), sql_text(r[2]), sql_text(r[3]), sql_int(r[4]) != 0});
  return out;
}

Result<std::optional<std::int64_t>> HistoryStore::recent_commit_time(const std::string& case_name, int back) {
  Result<std::vector<SqlRow>> rows = db_->query(
      "SELECT c.commit_time FROM sb_commits c WHERE EXISTS (SELECT 1 FROM sb_runs r WHERE r.commit_sha = c.sha "
      "AND (? = '' OR r.case_name = ?)) ORDER BY c.commit_time DESC, c.generation DESC, c.sha DESC LIMIT 1 OFFSET ?",
      {case_name, case_name, std::int64_t{back}});
  if (!rows) return rows.error();
  if (rows->empty()) return std::optional<std::int64_t>{};
  return std::optional<std::int64_t>{sql_int(rows->front()[0])};
}

Status HistoryStore::acknowledge(const Acknowledgement& ack) {
  WriteTransaction tx(*db_);
  if (!tx.started()) return tx.started();
  Result<std::vector<SqlRow>> done = db_->query(
      "INSERT INTO sb_acknowledgements (series_id, commit_sha, note, created_at) VALUES (?, ?, ?, ?) "
      "ON CONFLICT (series_id, commit_sha) DO UPDATE SET note = excluded.note",
      {ack.series_id, ack.commit, ack.note, ack.created.empty() ? now_utc() : ack.created});
  if (!done) return done.error();
  return tx.commit();
}

Result<std::vector<Acknowledgement>> HistoryStore::acknowledgements(std::int64_t series) {
  Result<std::vector<Acknowledgement>> all = all_acknowledgements();
  if (!all) return all.error();
  std::vector<Acknowledgement> out;
  for (Acknowledgement& a : *all)
    if (a.series_id == series) out.push_back(std::move(a));
  return out;
}

Result<std::vector<Acknowledgement>> HistoryStore::all_acknowledgements() {
  Result<std::vector<SqlRow>> rows = db_->query(
      "SELECT a.series_id, a.commit_sha, a.note, a.created_at, c.commit_time, c.generation FROM sb_acknowledgements a "
      "JOIN sb_commits c ON c.sha = a.commit_sha ORDER BY a.series_id, c.commit_time, c.generation, c.sha",
      {});
  if (!rows) return rows.error();
  std::vector<Acknowledgement> out;
  for (const SqlRow& r : *rows)
    out.push_back({sql_int(r[0]), sql_text(r[1]), sql_text(r[2]), sql_text(r[3]), sql_int(r[4]), sql_int(r[5])});
  return out;
}

}  // namespace shatter
