#include "harness/history/store/postgres_connection.h"

#include <fmt/core.h>
#include <libpq-fe.h>

#include <cstdlib>
#include <cstring>

namespace shatter {
namespace {

// Type OIDs of the built-in types (PostgreSQL's pg_type.dat).
constexpr Oid kBool = 16, kBytea = 17, kInt8 = 20, kInt2 = 21, kInt4 = 23, kText = 25, kFloat4 = 700,
              kFloat8 = 701, kNumeric = 1700;

/// libpq's messages span lines; errors here are one line.
std::string one_line(const char* text) {
  std::string s = text ? text : "";
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

/// `sql` with its `?` placeholders numbered `$1, $2, ...` (outside quoted text).
std::string numbered_placeholders(std::string_view sql) {
  std::string out;
  out.reserve(sql.size() + 16);
  int n = 0;
  char quote = 0;
  for (char c : sql) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '?') {
      out += fmt::format("${}", ++n);
      continue;
    }
    out += c;
  }
  return out;
}

class PostgresConnection final : public SqlConnection {
 public:
  PostgresConnection(PGconn* conn, std::string name) : conn_(conn), name_(std::move(name)) {}
  ~PostgresConnection() override { PQfinish(conn_); }

  std::string_view dialect() const override { return "postgresql"; }
  const std::string& name() const override { return name_; }
  std::string_view blob_type() const override { return "BYTEA"; }
  int max_parameters() const override { return 65535; }

  Status for_each_row(std::string_view sql, const std::vector<SqlValue>& params,
                      const std::function<Status(const SqlRow&)>& visit) override {
    const std::string text = numbered_placeholders(sql);
    std::vector<Oid> types(params.size(), 0);
    std::vector<std::string> held(params.size());
    std::vector<const char*> values(params.size(), nullptr);
    std::vector<int> lengths(params.size(), 0);
    std::vector<int> formats(params.size(), 0);
    for (std::size_t i = 0; i < params.size(); ++i) {
      const SqlValue& p = params[i];
      if (std::holds_alternative<std::monostate>(p)) continue;
      if (const auto* n = std::get_if<std::int64_t>(&p)) {
        types[i] = kInt8;
        held[i] = fmt::format("{}", *n);
      } else if (const auto* d = std::get_if<double>(&p)) {
        types[i] = kFloat8;
        held[i] = fmt::format("{}", *d);  // shortest text that reads back as the same double
      } else if (const auto* s = std::get_if<std::string>(&p)) {
        types[i] = kText;
        held[i] = *s;
      } else {
        types[i] = kBytea;
        held[i] = std::get<SqlBlob>(p).bytes;
        formats[i] = 1;
      }
      values[i] = held[i].data();
      lengths[i] = static_cast<int>(held[i].size());
    }
    if (!PQsendQueryParams(conn_, text.c_str(), static_cast<int>(params.size()), types.data(), values.data(),
                           lengths.data(), formats.data(), 0))
      return failure(nullptr);
    PQsetSingleRowMode(conn_);  // rows arrive one at a time: a large answer is never held whole
    Status status;
    SqlRow row;
    // Every result is read to the end, also after an error, so the connection is ready for the next query.
    while (PGresult* res = PQgetResult(conn_)) {
      std::unique_ptr<PGresult, void (*)(PGresult*)> guard(res, PQclear);
      const ExecStatusType st = PQresultStatus(res);
      if (st != PGRES_SINGLE_TUPLE) {
        if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK && status) status = failure(res);
        continue;
      }
      if (!status) continue;
      const int n_cols = PQnfields(res);
      row.assign(static_cast<std::size_t>(n_cols), SqlValue{});
      for (int c = 0; c < n_cols; ++c) {
        if (PQgetisnull(res, 0, c)) continue;
        const char* v = PQgetvalue(res, 0, c);
        switch (PQftype(res, c)) {
          case kInt2: case kInt4: case kInt8: row[c] = static_cast<std::int64_t>(std::strtoll(v, nullptr, 10)); break;
          case kBool: row[c] = static_cast<std::int64_t>(v[0] == 't' ? 1 : 0); break;
          case kFloat4: case kFloat8: case kNumeric: row[c] = std::strtod(v, nullptr); break;
          case kBytea: {
            std::size_t length = 0;
            unsigned char* bytes = PQunescapeBytea(reinterpret_cast<const unsigned char*>(v), &length);
            if (bytes == nullptr) {
              status = Error{name_ + ": out of memory reading a blob"};
              break;
            }
            row[c] = SqlBlob{std::string(reinterpret_cast<const char*>(bytes), length)};
            PQfreemem(bytes);
            break;
          }
          default: row[c] = std::string(v, static_cast<std::size_t>(PQgetlength(res, 0, c)));
        }
      }
      if (status) status = visit(row);
    }
    if (status && PQstatus(conn_) != CONNECTION_OK) status = failure(nullptr);
    return status;
  }

  Status begin_write() override { return command("BEGIN"); }
  Status commit() override { return command("COMMIT"); }
  void rollback() noexcept override {
    if (PQstatus(conn_) != CONNECTION_OK) return;
    if (PQtransactionStatus(conn_) == PQTRANS_IDLE) return;
    PQclear(PQexec(conn_, "ROLLBACK"));
  }
  Status lock_schema() override {
    // A fixed key: every shatterbench store on the server migrates one process at a time.
    Result<std::vector<SqlRow>> r = query("SELECT pg_advisory_xact_lock(5384729173)", {});
    return r ? Status{} : Status{r.error()};
  }

 private:
  Status command(const char* sql) {
    PGresult* res = PQexec(conn_, sql);
    std::unique_ptr<PGresult, void (*)(PGresult*)> guard(res, PQclear);
    if (PQresultStatus(res) != PGRES_COMMAND_OK) return failure(res);
    return {};
  }

  Error failure(const PGresult* res) const {
    if (PQstatus(conn_) != CONNECTION_OK)
      return Error{fmt::format("{}: the connection to the server was lost: {}", name_, one_line(PQerrorMessage(conn_)))};
    const char* message = res ? PQresultErrorMessage(res) : PQerrorMessage(conn_);
    return Error{fmt::format("{}: {}", name_, one_line(message))};
  }

  PGconn* conn_;
  std::string name_;
};

}  // namespace

bool is_postgres_url(std::string_view store) {
  return store.starts_with("postgresql://") || store.starts_with("postgres://");
}

/// `text` with every occurrence of `secret` (a password) replaced.
static std::string without(std::string text, const std::string& secret) {
  if (secret.empty()) return text;
  for (std::size_t at = text.find(secret); at != std::string::npos; at = text.find(secret, at))
    text.replace(at, secret.size(), "***");
  return text;
}

Result<std::unique_ptr<SqlConnection>> open_postgres(const std::string& url) {
  // The URL is parsed first, so that a malformed one gets a fixed message: libpq's would quote the
  // URL, password included.
  char* parse_error = nullptr;
  PQconninfoOption* parsed = PQconninfoParse(url.c_str(), &parse_error);
  if (parsed == nullptr) {
    if (parse_error != nullptr) PQfreemem(parse_error);
    return Error{"postgresql URL: cannot be read (expected postgresql://user[:password]@host[:port]/database[?key=value])"};
  }
  std::string password;
  for (PQconninfoOption* o = parsed; o->keyword != nullptr; ++o)
    if (std::strcmp(o->keyword, "password") == 0 && o->val != nullptr) password = o->val;
  PQconninfoFree(parsed);
  // Earlier keywords are overridden by what the URL sets (expand_dbname), so its own timeout wins.
  const char* keywords[] = {"connect_timeout", "application_name", "dbname", nullptr};
  const char* values[] = {"5", "shatterbench", url.c_str(), nullptr};
  PGconn* conn = PQconnectdbParams(keywords, values, 1);
  if (conn == nullptr) return Error{"postgresql: out of memory connecting"};
  if (PQstatus(conn) != CONNECTION_OK) {
    // The URL may hold a password: the error names the host and database only.
    const char* host = PQhost(conn);
    const char* port = PQport(conn);
    const char* db = PQdb(conn);
    std::string message = fmt::format("postgresql://{}:{}/{}: cannot connect: {}", host ? host : "?", port ? port : "?",
                                      db ? db : "?", without(one_line(PQerrorMessage(conn)), password));
    PQfinish(conn);
    return Error{message};
  }
  std::string name = fmt::format("postgresql://{}:{}/{}", PQhost(conn), PQport(conn), PQdb(conn));
  PQsetNoticeProcessor(conn, [](void*, const char*) {}, nullptr);  // "relation exists, skipping" and the like
  auto connection = std::make_unique<PostgresConnection>(conn, std::move(name));
  return std::unique_ptr<SqlConnection>(std::move(connection));
}

}  // namespace shatter
