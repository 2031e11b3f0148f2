#pragma once
/// The history store in an SQLite file (the default: `results/history.sqlite`).
///
/// The file is opened in WAL mode with a busy timeout, so readers never block a writer and two
/// recorders (CI shards on one machine) queue for the write lock instead of failing; a writer that
/// waits longer than the timeout gets a one-line "locked" error. A file that is not an SQLite
/// database is refused by SQLite's own check of its header.

#include "harness/history/store/sql_connection.h"

#include <filesystem>
#include <memory>

namespace shatter {

/// How to open an SQLite store.
struct SqliteOpenOptions {
  bool create = false;          ///< create the file (and its folder) when missing; else a missing file is an error
  double lock_timeout_s = 10.0; ///< longest wait for another process's lock, s
};

/// Opens `path`.
Result<std::unique_ptr<SqlConnection>> open_sqlite(const std::filesystem::path& path, const SqliteOpenOptions& options);

}  // namespace shatter
