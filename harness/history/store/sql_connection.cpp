#include "harness/history/store/sql_connection.h"

#include <cassert>

namespace shatter {
namespace {
const std::string kEmpty;
}  // namespace

std::int64_t sql_int(const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return 0;
  if (const double* d = std::get_if<double>(&v)) return static_cast<std::int64_t>(*d);
  assert(std::holds_alternative<std::int64_t>(v));
  return std::get<std::int64_t>(v);
}

double sql_double(const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return 0.0;
  if (const std::int64_t* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  assert(std::holds_alternative<double>(v));
  return std::get<double>(v);
}

const std::string& sql_text(const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return kEmpty;
  assert(std::holds_alternative<std::string>(v));
  return std::get<std::string>(v);
}

const std::string& sql_blob(const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return kEmpty;
  if (const std::string* s = std::get_if<std::string>(&v)) return *s;
  assert(std::holds_alternative<SqlBlob>(v));
  return std::get<SqlBlob>(v).bytes;
}

Result<std::vector<SqlRow>> SqlConnection::query(std::string_view sql, const std::vector<SqlValue>& params) {
  std::vector<SqlRow> rows;
  Status s = for_each_row(sql, params, [&rows](const SqlRow& row) {
    rows.push_back(row);
    return Status{};
  });
  if (!s) return s.error();
  return rows;
}

WriteTransaction::WriteTransaction(SqlConnection& db) : db_(db), started_(db.begin_write()), open_(started_.ok()) {}

WriteTransaction::~WriteTransaction() {
  if (open_) db_.rollback();
}

Status WriteTransaction::commit() {
  assert(open_);
  open_ = false;
  Status s = db_.commit();
  if (!s) db_.rollback();
  return s;
}

}  // namespace shatter
