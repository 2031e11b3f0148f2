#pragma once
/// The store's schema and its numbered migrations (docs/history.md, "Schema"). One schema serves
/// SQLite and PostgreSQL. `sb_schema` holds the version; opening a store brings an older one forward,
/// in one transaction per store, and refuses one newer than this binary.

#include "harness/history/store/sql_connection.h"

namespace shatter {

/// The version this binary writes.
inline constexpr int kHistorySchemaVersion = 3;

/// The schema version of `db` (0: no store yet).
Result<int> history_schema_version(SqlConnection& db);

/// Brings `db` to `target` (default: kHistorySchemaVersion), applying each migration above its
/// version in order, in one write transaction. Refuses a store newer than this binary, and an SQLite
/// file that holds other tables but no store (another program's database).
Status migrate_history_schema(SqlConnection& db, int target = kHistorySchemaVersion);

}  // namespace shatter
