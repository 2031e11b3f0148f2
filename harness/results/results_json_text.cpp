#include "harness/results/results_json_text.h"

#include <algorithm>
#include <string_view>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

/// Objects whose arrays of numbers are written on one line.
bool one_line_arrays_in(std::string_view key) { return key == "frame_stages_ms"; }

void indent(std::string& out, int depth) { out.append(static_cast<std::size_t>(depth), ' '); }

/// Writes `j` at `depth`. `one_line`: for an object, its number arrays go on one line; for an array,
/// it is such a member and goes on one line when it holds numbers only.
void write(std::string& out, const Json& j, int depth, bool one_line) {
  if (j.is_object()) {
    if (j.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!first) out += ",\n";
      first = false;
      indent(out, depth + 1);
      out += Json(it.key()).dump();
      out += ": ";
      write(out, it.value(), depth + 1, it->is_array() ? one_line : one_line_arrays_in(it.key()));
    }
    out += "\n";
    indent(out, depth);
    out += "}";
    return;
  }
  if (j.is_array()) {
    if (j.empty()) {
      out += "[]";
      return;
    }
    if (one_line && std::all_of(j.begin(), j.end(), [](const Json& v) { return v.is_number(); })) {
      out += "[";
      for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
      out += "]";
      return;
    }
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      if (i) out += ",\n";
      indent(out, depth + 1);
      write(out, j[i], depth + 1, false);
    }
    out += "\n";
    indent(out, depth);
    out += "]";
    return;
  }
  out += j.dump();
}

}  // namespace

std::string results_json_text(const nlohmann::ordered_json& j) {
  std::string out;
  write(out, j, 0, false);
  return out;
}

}  // namespace shatter
