#pragma once
/// One connection to the database that holds the history (docs/history.md, "The store"): SQLite for a
/// file on this machine, PostgreSQL for a team's server. The store's code is written once against this
/// interface; the two backends differ only in how they connect, bind and lock.
///
/// SQL is written with `?` placeholders and the types `BIGINT`, `DOUBLE PRECISION`, `TEXT` and the
/// backend's blob type (blob_type()), which both databases accept. Every value reaches the database
/// bound as a parameter, never pasted into the statement's text.

#include "algorithms/core/result.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace shatter {

/// Bytes of a BLOB (SQLite) or BYTEA (PostgreSQL) column.
struct SqlBlob {
  std::string bytes;
  friend bool operator==(const SqlBlob&, const SqlBlob&) = default;
};

/// One value: NULL, an integer, a double, text or a blob.
using SqlValue = std::variant<std::monostate, std::int64_t, double, std::string, SqlBlob>;

/// One row of a query's answer, its columns in the order of the SELECT.
using SqlRow = std::vector<SqlValue>;

/// The integer in `v` (0 for NULL; asserts on another type).
std::int64_t sql_int(const SqlValue& v);
/// The number in `v` (an integer converted; 0 for NULL).
double sql_double(const SqlValue& v);
/// The text in `v` ("" for NULL).
const std::string& sql_text(const SqlValue& v);
/// The bytes in `v` ("" for NULL).
const std::string& sql_blob(const SqlValue& v);

/// A connection. Not thread-safe: one per thread. Every error message starts with the store's name
/// (the file, or the server's host and database) and says what failed, on one line.
class SqlConnection {
 public:
  virtual ~SqlConnection() = default;
  /// "sqlite" or "postgresql".
  [[nodiscard]] virtual std::string_view dialect() const = 0;
  /// The store's name as errors show it.
  [[nodiscard]] virtual const std::string& name() const = 0;
  /// The type name of a blob column: "BLOB" or "BYTEA".
  [[nodiscard]] virtual std::string_view blob_type() const = 0;
  /// Runs one statement with `params` bound to its `?` in order and hands each row it returns to
  /// `row` as it arrives (large answers are never held whole); an error from `row` ends the query.
  virtual Status for_each_row(std::string_view sql, const std::vector<SqlValue>& params,
                              const std::function<Status(const SqlRow&)>& row) = 0;
  /// Runs one statement; the rows it returns (none for a statement that returns none).
  Result<std::vector<SqlRow>> query(std::string_view sql, const std::vector<SqlValue>& params = {});
  /// Starts a transaction that writes: SQLite takes the write lock now (BEGIN IMMEDIATE, waiting up to
  /// the busy timeout), so two writers queue instead of failing at their first write.
  virtual Status begin_write() = 0;
  /// Commits the open transaction.
  virtual Status commit() = 0;
  /// Rolls the open transaction back (nothing when none is open; errors are ignored: the connection
  /// may be gone, and the database then rolls back by itself).
  virtual void rollback() noexcept = 0;
  /// Takes a lock that serialises schema migrations between processes until the transaction ends
  /// (PostgreSQL's advisory lock; SQLite's write lock already does).
  virtual Status lock_schema() = 0;
  /// Most parameters one statement may bind.
  [[nodiscard]] virtual int max_parameters() const = 0;
};

/// A transaction that rolls back unless committed.
class WriteTransaction {
 public:
  /// Begins a write transaction on `db`; check started().
  explicit WriteTransaction(SqlConnection& db);
  ~WriteTransaction();
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  /// The begin's status.
  [[nodiscard]] const Status& started() const { return started_; }
  /// Commits; after this the destructor does nothing.
  Status commit();

 private:
  SqlConnection& db_;
  Status started_;
  bool open_ = false;
};

}  // namespace shatter
