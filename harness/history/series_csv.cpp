#include "harness/history/series_csv.h"

#include "algorithms/core/bounded_read.h"

#include <charconv>
#include <cmath>
#include <string_view>

namespace shatter {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

}  // namespace

Result<LabelledSeries> read_series_csv(const std::filesystem::path& path) {
  Result<std::string> text = read_file_bounded(path, kMaxSeriesCsvBytes, "series file");
  if (!text) return text.error();
  LabelledSeries series;
  std::string_view rest = *text;
  for (std::size_t line = 1; !rest.empty(); ++line) {
    const std::size_t end = rest.find('\n');
    const std::string_view row = trimmed(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (row.empty()) continue;
    const auto at = [&](const std::string& what) { return Error{path.string() + ":" + std::to_string(line) + ": " + what}; };
    const std::size_t comma = row.find(',');
    if (comma == std::string_view::npos || row.find(',', comma + 1) != std::string_view::npos)
      return at("expected two fields, commit,value");
    const std::string_view label = trimmed(row.substr(0, comma));
    const std::string_view field = trimmed(row.substr(comma + 1));
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (ec != std::errc() || ptr != field.data() + field.size() || !std::isfinite(value)) {
      if (series.values.empty() && label == "commit" && field == "value") continue;  // the header
      return at("the value '" + std::string(field.substr(0, 40)) + "' is not a finite number");
    }
    if (label.empty()) return at("the commit is empty");
    series.labels.emplace_back(label);
    series.values.push_back(value);
  }
  if (series.values.empty()) return Error{path.string() + ": holds no point (expected commit,value lines)"};
  return series;
}

}  // namespace shatter
