#include "harness/cases/json_reader.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace shatter {
namespace {

using nlohmann::json;

/// Thrown from the parser callback on a repeated key; caught in parse_json.
struct DuplicateKey {
  std::string key;
};

/// "string", "array", ... with an article, for "expected X, got Y" messages.
std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    case json::value_t::number_float: return fmt::format("{}", value.get<double>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return value.dump();
    default: return value.type_name();
  }
}

/// Line and column (both 1-based) of the character at 1-based byte `byte` of `text`.
std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t byte) {
  const std::size_t end = std::min(byte == 0 ? 0 : byte - 1, text.size());
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

/// The reason part of an nlohmann parse error ("syntax error while parsing ..."), on one line.
std::string parse_reason(const std::string& what) {
  std::string reason = what;
  if (const std::size_t at = what.find("column "); at != std::string::npos) {
    if (const std::size_t colon = what.find(": ", at); colon != std::string::npos) reason = what.substr(colon + 2);
  } else if (const std::size_t bracket = what.find("] "); bracket != std::string::npos) {
    reason = what.substr(bracket + 2);
  }
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  return reason;
}

}  // namespace

Result<json> parse_json(std::string_view text, const std::string& file) {
  // One set of seen keys per open object, to refuse repeated keys.
  std::vector<std::set<std::string>> open_objects;
  const json::parser_callback_t on_event = [&open_objects](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      open_objects.emplace_back();
    } else if (event == json::parse_event_t::object_end) {
      if (!open_objects.empty()) open_objects.pop_back();
    } else if (event == json::parse_event_t::key && !open_objects.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!open_objects.back().insert(key).second) throw DuplicateKey{key};
    }
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), on_event);
  } catch (const DuplicateKey& duplicate) {
    return Error{fmt::format("{}: key \"{}\" appears twice in one object", file, duplicate.key)};
  } catch (const json::parse_error& e) {
    const auto [line, column] = line_column(text, e.byte);
    return Error{fmt::format("{}: line {}, column {}: invalid JSON: {}", file, line, column, parse_reason(e.what()))};
  } catch (const std::exception& e) {
    // A number too large for a double is reported without a position: find its text instead.
    const std::string what = e.what();
    const std::size_t open = what.find('\'');
    const std::size_t close = open == std::string::npos ? open : what.find('\'', open + 1);
    if (close != std::string::npos && close > open + 1) {
      if (const std::size_t at = text.find(what.substr(open + 1, close - open - 1)); at != std::string_view::npos) {
        const auto [line, column] = line_column(text, at + 1);
        return Error{fmt::format("{}: line {}, column {}: invalid JSON: {}", file, line, column, parse_reason(what))};
      }
    }
    return Error{fmt::format("{}: invalid JSON: {}", file, parse_reason(what))};
  }
}

std::string escape_control_characters(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c != 0x7f) {
      out += ch;
    } else if (ch == '\n') {
      out += "\\n";
    } else if (ch == '\r') {
      out += "\\r";
    } else if (ch == '\t') {
      out += "\\t";
    } else {
      out += fmt::format("\\x{:02x}", c);
    }
  }
  return out;
}

std::string key_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return escape_control_characters(key);
  return fmt::format("{}.{}", parent, escape_control_characters(key));
}

std::string index_path(std::string_view parent, std::size_t index) { return fmt::format("{}[{}]", parent, index); }

void JsonReader::fail(std::string_view path, std::string_view what) {
  if (failed()) return;
  if (path.empty())
    error_ = Error{fmt::format("{}: {}", file_, what)};
  else
    error_ = Error{fmt::format("{}: {}: {}", file_, path, what)};
}

bool JsonReader::object(const json& value, std::string_view path, std::initializer_list<std::string_view> allowed) {
  if (failed()) return false;
  if (!value.is_object()) {
    fail(path, fmt::format("expected an object, got {}", describe(value)));
    return false;
  }
  for (const auto& item : value.items()) {
    bool known = false;
    for (std::string_view name : allowed) known = known || item.key() == name;
    if (!known) {
      fail(key_path(path, item.key()), fmt::format("unknown key (allowed: {})", fmt::join(allowed, ", ")));
      return false;
    }
  }
  return true;
}

bool JsonReader::array(const json& value, std::string_view path) {
  if (failed()) return false;
  if (!value.is_array()) {
    fail(path, fmt::format("expected an array, got {}", describe(value)));
    return false;
  }
  return true;
}

bool JsonReader::convert(const json& value, std::string_view path, bool& out) {
  if (failed()) return false;
  if (!value.is_boolean()) {
    fail(path, fmt::format("expected true or false, got {}", describe(value)));
    return false;
  }
  out = value.get<bool>();
  return true;
}

bool JsonReader::convert(const json& value, std::string_view path, double& out) {
  if (failed()) return false;
  if (!value.is_number()) {
    fail(path, fmt::format("expected a number, got {}", describe(value)));
    return false;
  }
  const double v = value.get<double>();
  if (!std::isfinite(v)) {
    fail(path, "must be a finite number");
    return false;
  }
  out = v;
  return true;
}

bool JsonReader::convert(const json& value, std::string_view path, int& out) {
  if (failed()) return false;
  if (!value.is_number_integer()) {
    fail(path, fmt::format("expected an integer, got {}", describe(value)));
    return false;
  }
  constexpr auto lo = std::numeric_limits<int>::min();
  constexpr auto hi = std::numeric_limits<int>::max();
  const bool fits = value.is_number_unsigned() ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(hi)
                                               : value.get<std::int64_t>() >= lo && value.get<std::int64_t>() <= hi;
  if (!fits) {
    fail(path, fmt::format("integer out of range, got {}", value.dump()));
    return false;
  }
  out = value.get<int>();
  return true;
}

bool JsonReader::convert(const json& value, std::string_view path, std::uint64_t& out) {
  if (failed()) return false;
  if (!value.is_number_integer() || (!value.is_number_unsigned() && value.get<std::int64_t>() < 0)) {
    fail(path, fmt::format("expected a non-negative integer, got {}", describe(value)));
    return false;
  }
  out = value.get<std::uint64_t>();
  return true;
}

bool JsonReader::convert(const json& value, std::string_view path, std::string& out) {
  if (failed()) return false;
  if (!value.is_string()) {
    fail(path, fmt::format("expected a string, got {}", describe(value)));
    return false;
  }
  out = value.get<std::string>();
  return true;
}

bool JsonReader::convert(const json& value, std::string_view path, Vec3& out) {
  if (failed()) return false;
  if (!value.is_array() || value.size() != 3) {
    fail(path, fmt::format("expected an array of 3 numbers [x, y, z], got {}",
                           value.is_array() ? fmt::format("{} elements", value.size()) : describe(value)));
    return false;
  }
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i)
    if (!convert(value[i], index_path(path, i), v[static_cast<Eigen::Index>(i)])) return false;
  out = v;
  return true;
}

bool JsonReader::positive(std::string_view path, double value) {
  if (value > 0.0) return true;
  fail(path, fmt::format("must be > 0, got {}", value));
  return false;
}

bool JsonReader::non_negative(std::string_view path, double value) {
  if (value >= 0.0) return true;
  fail(path, fmt::format("must be >= 0, got {}", value));
  return false;
}

bool JsonReader::at_least(std::string_view path, std::int64_t value, std::int64_t min) {
  if (value >= min) return true;
  fail(path, fmt::format("must be >= {}, got {}", min, value));
  return false;
}

bool JsonReader::at_most(std::string_view path, std::int64_t value, std::int64_t max) {
  if (value <= max) return true;
  fail(path, fmt::format("must be <= {}, got {}", max, value));
  return false;
}

bool JsonReader::non_zero(std::string_view path, const Vec3& value) {
  if ((value.array() != 0.0).any()) return true;
  fail(path, "must be a non-zero vector, got [0, 0, 0]");
  return false;
}

}  // namespace shatter
