#include "harness/results/json_finite.h"

#include <cstdint>
#include <vector>

namespace shatter {
namespace {

using Json = nlohmann::json;

/// A SAX handler that only keeps track of where it is ("cells[2].samples[0].frame_ms[7]") and
/// remembers that place when the parse fails.
class PathTracker {
 public:
  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(Json::number_integer_t) { return value(); }
  bool number_unsigned(Json::number_unsigned_t) { return value(); }
  bool number_float(Json::number_float_t, const Json::string_t&) { return value(); }
  bool string(Json::string_t&) { return value(); }
  bool binary(Json::binary_t&) { return value(); }
  bool start_object(std::size_t) {
    levels_.push_back({false, 0, {}});
    return true;
  }
  bool key(Json::string_t& k) {
    levels_.back().key = k;
    return true;
  }
  bool end_object() { return end(); }
  bool start_array(std::size_t) {
    levels_.push_back({true, 0, {}});
    return true;
  }
  bool end_array() { return end(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
    error_path_ = path();
    return false;
  }
  [[nodiscard]] const std::string& error_path() const { return error_path_; }

 private:
  struct Level {
    bool array = false;
    std::size_t index = 0;  // of the element being read
    std::string key;        // of the member being read
  };

  bool value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
    return true;
  }
  bool end() {
    levels_.pop_back();
    return value();
  }
  [[nodiscard]] std::string path() const {
    std::string out;
    for (const Level& l : levels_) {
      if (l.array) {
        out += '[';
        out += std::to_string(l.index);
        out += ']';
      } else {
        if (!out.empty()) out += '.';
        out += l.key;
      }
    }
    return out;
  }

  std::vector<Level> levels_;
  std::string error_path_;
};

}  // namespace

Result<nlohmann::ordered_json> parse_results_json(std::string_view text, const std::string& file) {
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    PathTracker tracker;
    Json::sax_parse(text, &tracker);
    const std::string where = tracker.error_path().empty() ? std::string() : tracker.error_path() + ": ";
    if (e.id == 406)  // out_of_range.406: a number that overflows a double
      return Error{file + ": " + where + "a number that is not finite (too large for a double)"};
    return Error{file + ": " + where + "invalid JSON: " + e.what()};
  }
}

}  // namespace shatter
