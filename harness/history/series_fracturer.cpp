#include "harness/history/series_fracturer.h"

#include <string_view>

namespace shatter {
namespace {

/// The `n`-th (from 0) space-separated word of `text`; empty when it has fewer.
std::string_view word(std::string_view text, int n) {
  std::size_t start = 0;
  for (int k = 0; k <= n; ++k) {
    while (start < text.size() && text[start] == ' ') ++start;
    if (start >= text.size()) return {};
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    if (k == n) return text.substr(start, end - start);
    start = end;
  }
  return {};
}

}  // namespace

std::string series_fracturer(const SeriesKey& key) {
  if (key.kind == "grid") {
    // "100 x 25 plane-slice/voronoi/von-mises [schedule]": the fourth word, between its slashes.
    const std::string_view names = word(key.subject, 3);
    const std::size_t first = names.find('/');
    const std::size_t second = first == std::string_view::npos ? first : names.find('/', first + 1);
    if (second == std::string_view::npos) return {};
    return std::string(names.substr(first + 1, second - first - 1));
  }
  return std::string(word(key.subject, 0));
}

}  // namespace shatter
