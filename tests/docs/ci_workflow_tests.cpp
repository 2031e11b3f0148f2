// The CI workflow in docs/ci/ is valid YAML (yaml-cpp) and names only what exists: the scripts of
// scripts/, and the shatterbench commands and flags the built CLI lists in its --help.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

/// The shell words of `line` (quotes removed; no expansion).
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::string word;
  char quote = 0;
  bool in_word = false;
  for (const char c : line) {
    if (quote != 0) {
      if (c == quote) quote = 0;
      else word += c;
      continue;
    }
    if (c == '"' || c == '\'') {
      quote = c;
      in_word = true;
      continue;
    }
    if (c == ' ' || c == '\t') {
      if (in_word) out.push_back(word);
      word.clear();
      in_word = false;
      continue;
    }
    word += c;
    in_word = true;
  }
  if (in_word) out.push_back(word);
  return out;
}

/// The logical lines of a `run` script: continuation lines (ending in a backslash) joined.
std::vector<std::string> logical_lines(const std::string& script) {
  std::vector<std::string> out;
  std::istringstream in(script);
  std::string line, joined;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\\') {
      joined += line.substr(0, line.size() - 1) + " ";
      continue;
    }
    out.push_back(joined + line);
    joined.clear();
  }
  if (!joined.empty()) out.push_back(joined);
  return out;
}

/// What the built CLI's --help of `command` says (cached); `command` may be a command and its
/// subcommand ("history gate").
const std::string& help_of(const std::string& command) {
  static std::map<std::string, std::string> cache;
  auto it = cache.find(command);
  if (it == cache.end()) {
    std::vector<std::string> args = words(command);
    args.push_back("--help");
    const test::CliRun run = test::run_cli_argv(args);
    REQUIRE(run.exit_code == 0);
    it = cache.emplace(command, run.out).first;
  }
  return it->second;
}

/// Problems with one logical line: a script of scripts/ that does not exist, a shatterbench command
/// or flag its --help does not list.
std::vector<std::string> problems_of(const std::string& line) {
  std::vector<std::string> out;
  const std::vector<std::string> w = words(line);
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w[i].rfind("scripts/", 0) == 0 && !fs::exists(fs::path(SHATTER_SOURCE_DIR) / w[i]))
      out.push_back("no script " + w[i]);
    const bool cli = w[i] == "shatterbench" || (w[i].size() > 13 && w[i].ends_with("/shatterbench"));
    if (!cli) continue;
    if (i + 1 >= w.size()) {
      out.push_back("shatterbench without a command");
      continue;
    }
    std::string command = w[i + 1];
    if (help_of("").find("\n  " + command + " ") == std::string::npos) {
      out.push_back("no command " + command);
      continue;
    }
    std::size_t first_flag = i + 2;
    if (command == "history") {  // a command of subcommands: its flags are the subcommand's
      if (first_flag >= w.size() || help_of("history").find("\n  " + w[first_flag] + " ") == std::string::npos) {
        out.push_back("no history subcommand " + (first_flag < w.size() ? w[first_flag] : std::string()));
        continue;
      }
      command += " " + w[first_flag++];
    }
    for (std::size_t k = first_flag; k < w.size(); ++k) {
      if (w[k] == "||" || w[k] == "&&" || w[k] == "|" || w[k] == ";") break;
      if (w[k].rfind("--", 0) != 0) continue;
      const std::string flag = w[k].substr(0, w[k].find('='));
      if (help_of(command).find("  " + flag + " ") == std::string::npos &&
          help_of(command).find("  " + flag + "\n") == std::string::npos &&
          help_of(command).find(", " + flag + " ") == std::string::npos)
        out.push_back(command + " has no flag " + flag);
    }
  }
  return out;
}

}  // namespace

namespace {

/// Checks one workflow file; the number of shatterbench calls in it.
int check_workflow(const std::string& name) {
  const fs::path file = fs::path(SHATTER_SOURCE_DIR) / "docs" / "ci" / name;
  REQUIRE(fs::exists(file));
  YAML::Node doc;
  REQUIRE_NOTHROW(doc = YAML::LoadFile(file.string()));
  REQUIRE(doc["jobs"].IsMap());
  REQUIRE(doc["on"]);
  int runs = 0, calls = 0;
  for (const auto& job : doc["jobs"]) {
    INFO(name << ": job " << job.first.as<std::string>());
    REQUIRE(job.second["runs-on"]);
    REQUIRE(job.second["steps"].IsSequence());
    for (const auto& step : job.second["steps"]) {
      REQUIRE(step.IsMap());
      CHECK((step["run"] || step["uses"]));
      if (!step["run"]) continue;
      ++runs;
      for (const std::string& line : logical_lines(step["run"].as<std::string>())) {
        INFO(line);
        CHECK(problems_of(line).empty());
        calls += line.find("shatterbench ") != std::string::npos ? 1 : 0;
      }
    }
  }
  CHECK(runs >= 4);
  return calls;
}

}  // namespace

TEST_CASE("ci workflow: valid YAML that names only commands, flags and scripts that exist", "[docs][cli]") {
  CHECK(check_workflow("shatterbench-gate.yml") >= 3);     // grid, merge, compare
  CHECK(check_workflow("shatterbench-history.yml") >= 3);  // grid, history record, history gate

  // The checks can fail: a command, a flag and a script that do not exist are found.
  CHECK(problems_of("build/bin/shatterbench grid --case x --no-such-flag 1").size() == 1);
  CHECK(problems_of("build/bin/shatterbench frobnicate --json a").size() == 1);
  CHECK(problems_of("scripts/no-such-script").size() == 1);
  CHECK(problems_of("build/bin/shatterbench compare a b --junit x --markdown y || test $? -eq 1").empty());
  CHECK(problems_of("build/bin/shatterbench history gate --commit x --markdown y").empty());
  CHECK(problems_of("build/bin/shatterbench history gate --commit x --max-slowdown 1").size() == 1);
  CHECK(problems_of("build/bin/shatterbench history frobnicate --db x").size() == 1);
}
