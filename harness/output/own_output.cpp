#include "harness/output/own_output.h"

#include <fstream>
#include <string>
#include <string_view>

namespace shatter {
namespace {

/// How much of a file is read to recognise it: the context block of every JSON output comes first
/// or second, well inside this.
constexpr std::size_t kHeadBytes = 16384;

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

bool contains(std::string_view text, std::string_view part) { return text.find(part) != std::string_view::npos; }

}  // namespace

bool is_own_output_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::string head(kHeadBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.empty()) return true;
  // A grid's recorded frames (results/recorded_frames.h): binary, recognised by their magic.
  if (starts_with(head, "SBFRAMES")) return true;
  std::string_view text(head);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return true;  // white space only
  text.remove_prefix(first);
  // Results, accuracy, stability and Google Benchmark JSON: the run context (results/run_context.h).
  if (starts_with(text, "{"))
    return contains(text, "\"fingerprint\"") && contains(text, "\"bullet_version\"") &&
           contains(text, "\"cgal_version\"");
  // The grid CSV (results/grid_csv_reporter.cpp).
  if (starts_with(text, "prefracture,runtime,prefracturer,fracturer,stress,")) return true;
  // JUnit reports of grid and compare (results/junit.cpp).
  if (starts_with(text, "<?xml")) return contains(text, "<testsuites>") && contains(text, "<testsuite name=\"shatterbench.");
  // The compare comment (compare/grid_compare.cpp).
  return starts_with(text, "### shatterbench compare");
}

}  // namespace shatter
