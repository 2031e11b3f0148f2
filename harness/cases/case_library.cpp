#include "harness/cases/case_library.h"

#include "harness/cases/case_loader.h"
#include "harness/cases/json_reader.h"
#include "harness/limits.h"

#include "algorithms/core/bounded_read.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <map>

namespace shatter {
namespace {

namespace fs = std::filesystem;

/// The candidate folders, existing or not, in search order.
std::vector<fs::path> candidate_dirs() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("SHATTER_CASE_DIR"); env != nullptr && *env != '\0') dirs.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && !exe.empty()) {
    dirs.push_back((exe.parent_path() / ".." / "share" / "shatterbench" / "cases").lexically_normal());  // installed
    dirs.push_back((exe.parent_path() / ".." / ".." / "cases").lexically_normal());                  // build/bin
  }
#ifdef SHATTER_INSTALLED_CASE_DIR
  dirs.emplace_back(SHATTER_INSTALLED_CASE_DIR);
#endif
#ifdef SHATTER_SOURCE_DIR
  dirs.push_back(fs::path(SHATTER_SOURCE_DIR) / "cases");
#endif
  dirs.emplace_back("cases");
  return dirs;
}

/// The "description" of a case file as written, or why it cannot be read.
std::string read_description_text(const fs::path& path) {
  const Result<std::string> text = read_file_bounded(path, kMaxCaseFileBytes, "case file");
  if (!text) return "invalid case file: " + text.error().message;
  Result<nlohmann::json> json = parse_json(*text, path.string());
  if (!json) return "invalid case file: " + json.error().message;
  if (!json->is_object()) return "invalid case file: not a JSON object";
  const auto it = json->find("description");
  return it != json->end() && it->is_string() ? it->get<std::string>() : std::string();
}

/// Characters of a description that `list` prints: one line of a table, not the file's content.
constexpr std::size_t kMaxListedDescription = 200;

/// The "description" of a case file, read without checking the rest of the file, as one short line
/// (control characters escaped, cut at kMaxListedDescription characters).
std::string read_description(const fs::path& path) {
  std::string text = escape_control_characters(read_description_text(path));
  if (text.size() <= kMaxListedDescription) return text;
  std::size_t cut = kMaxListedDescription;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return text.substr(0, cut) + "...";
}

/// True when `arg` reads as a file path rather than a case name.
bool looks_like_path(const std::string& arg) {
  return arg.find('/') != std::string::npos || fs::path(arg).extension() == ".json";
}

}  // namespace

std::vector<fs::path> case_search_dirs() {
  std::vector<fs::path> dirs;
  std::vector<fs::path> seen;  // canonical forms, to drop a folder reached twice
  for (const fs::path& dir : candidate_dirs()) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    const fs::path canonical = fs::weakly_canonical(dir, ec);
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) continue;
    seen.push_back(canonical);
    dirs.push_back(dir);
  }
  return dirs;
}

Result<Case> find_case(const std::string& name_or_path) {
  if (name_or_path.empty()) return Error{"empty case name: give a built-in case name or a case file"};
  std::error_code ec;
  if (fs::is_regular_file(name_or_path, ec)) return load_case(name_or_path);
  if (looks_like_path(name_or_path)) return Error{fmt::format("{}: case file not found", name_or_path)};
  const std::vector<fs::path> dirs = case_search_dirs();
  for (const fs::path& dir : dirs) {
    const fs::path file = dir / (name_or_path + ".json");
    if (fs::is_regular_file(file, ec)) return load_case(file);
  }
  std::vector<std::string> names;
  for (const BuiltinCase& c : list_builtin_cases()) names.push_back(c.name);
  std::vector<std::string> searched;
  for (const fs::path& dir : dirs) searched.push_back(dir.string());
  return Error{fmt::format("unknown case \"{}\": not a file, and no {}.json in [{}]; built-in cases: {}",
                           name_or_path, name_or_path, fmt::join(searched, ", "),
                           names.empty() ? std::string("none found") : fmt::format("{}", fmt::join(names, ", ")))};
}

std::vector<BuiltinCase> list_builtin_cases() {
  std::map<std::string, BuiltinCase> by_name;  // sorted; the first folder wins
  for (const fs::path& dir : case_search_dirs()) {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
      const fs::path& path = entry.path();
      if (path.extension() != ".json" || !entry.is_regular_file(ec)) continue;
      const std::string name = path.stem().string();
      if (by_name.count(name) != 0) continue;
      by_name.emplace(name, BuiltinCase{name, read_description(path), path});
    }
  }
  std::vector<BuiltinCase> out;
  for (auto& [name, c] : by_name) out.push_back(std::move(c));
  return out;
}

}  // namespace shatter
