#include "harness/history/store/sqlite_connection.h"

#include <fmt/core.h>
#include <sqlite3.h>

#include <cmath>
#include <system_error>

namespace shatter {
namespace {

class SqliteConnection final : public SqlConnection {
 public:
  SqliteConnection(sqlite3* db, std::string name, double lock_timeout_s)
      : db_(db), name_(std::move(name)), lock_timeout_s_(lock_timeout_s) {}
  ~SqliteConnection() override { sqlite3_close_v2(db_); }

  std::string_view dialect() const override { return "sqlite"; }
  const std::string& name() const override { return name_; }
  std::string_view blob_type() const override { return "BLOB"; }
  int max_parameters() const override { return sqlite3_limit(db_, SQLITE_LIMIT_VARIABLE_NUMBER, -1); }

  Status for_each_row(std::string_view sql, const std::vector<SqlValue>& params,
                      const std::function<Status(const SqlRow&)>& visit) override {
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt, nullptr) != SQLITE_OK)
      return failure(sqlite3_errcode(db_));
    std::unique_ptr<sqlite3_stmt, int (*)(sqlite3_stmt*)> guard(stmt, sqlite3_finalize);
    for (std::size_t i = 0; i < params.size(); ++i) {
      const int at = static_cast<int>(i) + 1;
      const SqlValue& p = params[i];
      int rc = SQLITE_OK;
      if (std::holds_alternative<std::monostate>(p)) rc = sqlite3_bind_null(stmt, at);
      else if (const auto* n = std::get_if<std::int64_t>(&p)) rc = sqlite3_bind_int64(stmt, at, *n);
      else if (const auto* d = std::get_if<double>(&p)) rc = sqlite3_bind_double(stmt, at, *d);
      else if (const auto* s = std::get_if<std::string>(&p))
        rc = sqlite3_bind_text64(stmt, at, s->data(), s->size(), SQLITE_STATIC, SQLITE_UTF8);
      else {
        const std::string& b = std::get<SqlBlob>(p).bytes;
        rc = sqlite3_bind_blob64(stmt, at, b.data(), b.size(), SQLITE_STATIC);
      }
      if (rc != SQLITE_OK) return failure(rc);
    }
    SqlRow row;
    for (;;) {
      const int rc = sqlite3_step(stmt);
      if (rc == SQLITE_DONE) break;
      if (rc != SQLITE_ROW) return failure(rc);
      const int n = sqlite3_column_count(stmt);
      row.assign(static_cast<std::size_t>(n), SqlValue{});
      for (int c = 0; c < n; ++c) {
        switch (sqlite3_column_type(stmt, c)) {
          case SQLITE_INTEGER: row[c] = static_cast<std::int64_t>(sqlite3_column_int64(stmt, c)); break;
          case SQLITE_FLOAT: row[c] = sqlite3_column_double(stmt, c); break;
          case SQLITE_TEXT:
            row[c] = std::string(reinterpret_cast<const char*>(sqlite3_column_text(stmt, c)),
                                 static_cast<std::size_t>(sqlite3_column_bytes(stmt, c)));
            break;
          case SQLITE_BLOB: {
            const void* p = sqlite3_column_blob(stmt, c);
            row[c] = SqlBlob{std::string(static_cast<const char*>(p), static_cast<std::size_t>(sqlite3_column_bytes(stmt, c)))};
            break;
          }
          default: break;  // NULL
        }
      }
      if (Status s = visit(row); !s) return s;
    }
    return {};
  }

  Status begin_write() override { return run("BEGIN IMMEDIATE"); }
  Status commit() override { return run("COMMIT"); }
  void rollback() noexcept override {
    if (sqlite3_get_autocommit(db_) == 0) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
  }
  Status lock_schema() override { return {}; }

 private:
  Status run(const char* sql) {
    if (sqlite3_exec(db_, sql, nullptr, nullptr, nullptr) != SQLITE_OK) return failure(sqlite3_errcode(db_));
    return {};
  }

  Error failure(int rc) const {
    if ((rc & 0xff) == SQLITE_BUSY || (rc & 0xff) == SQLITE_LOCKED)
      return Error{fmt::format("{}: the store is locked by another process (waited {:g} s)", name_, lock_timeout_s_)};
    return Error{fmt::format("{}: {}", name_, sqlite3_errmsg(db_))};
  }

  sqlite3* db_;
  std::string name_;
  double lock_timeout_s_;
};

}  // namespace

Result<std::unique_ptr<SqlConnection>> open_sqlite(const std::filesystem::path& path, const SqliteOpenOptions& options) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_regular_file(status)) return Error{name + ": not a regular file"};
    // An empty file is no store; opening it would write SQLite's header into it.
    if (!options.create && std::filesystem::file_size(path, ec) == 0 && !ec)
      return Error{name + ": no history store here (record a run first: shatterbench history record)"};
  } else if (!options.create) {
    return Error{name + ": no history store here (record a run first: shatterbench history record)"};
  } else if (path.has_parent_path()) {
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) return Error{fmt::format("{}: cannot create its folder: {}", name, ec.message())};
  }
  sqlite3* db = nullptr;
  const int flags = SQLITE_OPEN_READWRITE | (options.create ? SQLITE_OPEN_CREATE : 0) | SQLITE_OPEN_NOMUTEX;
  const int rc = sqlite3_open_v2(name.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    std::string message = fmt::format("{}: cannot open: {}", name, db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
    sqlite3_close_v2(db);
    return Error{message};
  }
  auto connection = std::make_unique<SqliteConnection>(db, name, options.lock_timeout_s);
  sqlite3_busy_timeout(db, static_cast<int>(std::lround(options.lock_timeout_s * 1000.0)));
  sqlite3_extended_result_codes(db, 1);
  // WAL: readers and one writer at once; FULL: a committed run survives a crash of the machine too.
  // Reads through a memory map and a 64 MiB page cache: a series' measurements are spread over the
  // whole file (one run after another), and read() of every page was most of a long query's time.
  for (const char* pragma : {"PRAGMA journal_mode=WAL", "PRAGMA synchronous=FULL", "PRAGMA foreign_keys=ON",
                             "PRAGMA mmap_size=4294967296", "PRAGMA cache_size=-65536"}) {
    Result<std::vector<SqlRow>> r = connection->query(pragma, {});
    if (!r) return r.error();
  }
  return std::unique_ptr<SqlConnection>(std::move(connection));
}

}  // namespace shatter
