#pragma once
/// Finding a non-finite number in a parsed results file. JSON has no NaN or Inf, but a number too large
/// for a double (1e999) parses as Inf, and a results file is the input of compare, merge and report:
/// one Inf there makes medians, changes and ratios Inf or NaN. Every reader of a results file refuses
/// the file when this finds one, naming the key (docs/stability.md, "no silent wrong number").

#include "algorithms/core/result.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace shatter {

/// The key path of the first number in `j` (depth first, in document order) that is not finite, e.g.
/// "cells[2].samples[0].frame_ms[7]"; nothing when every number is finite. `path` prefixes the result.
template <class Json>
std::optional<std::string> first_non_finite(const Json& j, const std::string& path = "") {
  if (j.is_number_float()) {
    if (!std::isfinite(j.template get<double>())) return path.empty() ? std::string("(top level)") : path;
    return std::nullopt;
  }
  if (j.is_array()) {
    std::size_t i = 0;
    for (const auto& item : j) {
      if (auto bad = first_non_finite(item, path + "[" + std::to_string(i) + "]")) return bad;
      ++i;
    }
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (auto bad = first_non_finite(it.value(), path.empty() ? it.key() : path + "." + it.key())) return bad;
  }
  return std::nullopt;
}

/// Parses the text of a results file read from `file`. nlohmann refuses a number that overflows a
/// double while parsing (out_of_range 406, not a parse_error); either error becomes `<file>: <key
/// path>: <what>`, the key path found by a second, path-tracking pass over the text.
Result<nlohmann::ordered_json> parse_results_json(std::string_view text, const std::string& file);

}  // namespace shatter
