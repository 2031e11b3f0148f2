#pragma once
/// The history store on a PostgreSQL server (`postgresql://user@host:port/db`), for a team whose CI
/// runners share one store. libpq from Debian (libpq-dev).
///
/// The connection gives up after 5 s unless the URL sets its own `connect_timeout`. Errors name the
/// server as host:port/database, never the password.

#include "harness/history/store/sql_connection.h"

#include <memory>
#include <string>

namespace shatter {

/// True when `store` names a PostgreSQL server (starts with `postgresql://` or `postgres://`).
bool is_postgres_url(std::string_view store);

/// Connects to `url`.
Result<std::unique_ptr<SqlConnection>> open_postgres(const std::string& url);

}  // namespace shatter
