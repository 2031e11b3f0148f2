#pragma once
/// Checked reading of a JSON settings file: typed values whose errors name the file and the key path
/// (`cases/x.json: material.density: expected a number, got string`), unknown keys refused, and JSON
/// syntax errors reported with line and column. nlohmann::json exceptions never escape.
///
/// Design note: the reader keeps the first error only and, after it, every read leaves its output
/// unchanged. A loader therefore reads a whole file straight through, without an early return after
/// every key, and checks failed() once at the end; the user sees the first problem in file order.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace shatter {

/// Parses JSON text. A syntax error gives `<file>: line L, column C: invalid JSON: <reason>`; a key
/// repeated within one object is an error too (JSON would silently keep the last one).
Result<nlohmann::json> parse_json(std::string_view text, const std::string& file);

/// `text` with every control character (below 0x20, and 0x7f) written as an escape (\n, \t, \x01),
/// so that a message quoting user input stays on one line.
std::string escape_control_characters(std::string_view text);

/// Path of member `key` of the object at `parent` ("" is the root): "material.density".
std::string key_path(std::string_view parent, std::string_view key);

/// Path of element `index` of the array at `parent`: "impacts[2]".
std::string index_path(std::string_view parent, std::size_t index);

/// Reads typed values from one parsed file, keeping the first error.
class JsonReader {
 public:
  /// `file` names the file in every message.
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  /// True once any check has failed.
  [[nodiscard]] bool failed() const { return error_.has_value(); }
  /// The first error; only valid when failed().
  [[nodiscard]] const Error& error() const { return *error_; }
  /// Records `<file>: <path>: <what>` unless an error is already recorded.
  void fail(std::string_view path, std::string_view what);

  /// Checks that `value` is an object whose keys are all in `allowed`; false (and an error naming
  /// the first unknown key's path and the allowed keys) otherwise.
  bool object(const nlohmann::json& value, std::string_view path,
              std::initializer_list<std::string_view> allowed);
  /// Checks that `value` is an array.
  bool array(const nlohmann::json& value, std::string_view path);

  /// Converts `value` at `path` into `out`; false (and an error naming the expected type) when it
  /// does not fit: a finite number for double, an integer in range for the integer types, a string,
  /// or an array of three finite numbers for Vec3.
  bool convert(const nlohmann::json& value, std::string_view path, bool& out);
  bool convert(const nlohmann::json& value, std::string_view path, double& out);
  bool convert(const nlohmann::json& value, std::string_view path, int& out);
  bool convert(const nlohmann::json& value, std::string_view path, std::uint64_t& out);
  bool convert(const nlohmann::json& value, std::string_view path, std::string& out);
  bool convert(const nlohmann::json& value, std::string_view path, Vec3& out);

  /// Reads member `key` of `obj` (at `parent`) into `out`, which keeps its value (the default) when
  /// the key is absent. True only when the key was present and read.
  template <class T>
  bool read(const nlohmann::json& obj, std::string_view parent, std::string_view key, T& out) {
    if (failed() || !obj.is_object()) return false;
    const auto it = obj.find(key);
    if (it == obj.end()) return false;
    return convert(*it, key_path(parent, key), out);
  }

  /// Like read(), but an absent key is an error ("missing required key").
  template <class T>
  bool read_required(const nlohmann::json& obj, std::string_view parent, std::string_view key, T& out) {
    if (failed() || !obj.is_object()) return false;
    if (!obj.contains(key)) {
      fail(key_path(parent, key), "missing required key");
      return false;
    }
    return read(obj, parent, key, out);
  }

  /// Range checks: record `must be > 0, got -3` style errors at `path`; true when the check passed.
  bool positive(std::string_view path, double value);
  bool non_negative(std::string_view path, double value);
  bool at_least(std::string_view path, std::int64_t value, std::int64_t min);
  bool at_most(std::string_view path, std::int64_t value, std::int64_t max);
  /// Checks that `value` is not the zero vector.
  bool non_zero(std::string_view path, const Vec3& value);

 private:
  std::string file_;
  std::optional<Error> error_;
};

}  // namespace shatter
