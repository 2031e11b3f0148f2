// Hostile input, child processes: valgrind, gnuplot and the isolated cell start from an argument
// vector, so quotes, `$()`, spaces, newlines and non-ASCII bytes in paths are data, never commands.

#include "harness/process/child_process.h"
#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// A folder name holding every character a shell would read as syntax, plus a newline and non-ASCII.
const std::string kHostileName = "O'Brien \"quoted\" $(touch PWNED) `touch PWNED2` ; touch PWNED3 \n Zürich";

}  // namespace

TEST_CASE("no shell: a child's arguments arrive as written", "[hostile][no-shell]") {
  const fs::path dir = hostile_scratch("child_args");
  const fs::path target = dir / kHostileName;
  ChildOptions options;
  options.working_folder = dir;
  const Result<ChildExit> made = run_child({"mkdir", target.string()}, options);
  REQUIRE(made.ok());
  CHECK(made->exited);
  CHECK(made->code == 0);
  CHECK(fs::is_directory(target));
  // A relative output file is taken against this process's folder, not the child's.
  const Result<ChildExit> listed = run_child({"ls", "-1", "-b"}, ChildOptions{dir, dir / "ls.txt", {}});
  REQUIRE(listed.ok());
  CHECK_FALSE(file_bytes(dir / "ls.txt").empty());
  for (const char* planted : {"PWNED", "PWNED2", "PWNED3"}) {
    CHECK_FALSE(fs::exists(dir / planted));
    CHECK_FALSE(fs::exists(fs::current_path() / planted));
  }
  const Result<ChildExit> missing = run_child({"no-such-program-" + kHostileName});
  REQUIRE_FALSE(missing.ok());
  CHECK_THAT(missing.error().message, Catch::Contains("cannot run"));
  CHECK(program_runs("true", ""));
  CHECK_FALSE(program_runs("false", ""));
}

TEST_CASE("no shell: report draws into a folder whose path a shell would misread", "[hostile][no-shell][cli]") {
  const fs::path dir = hostile_scratch("report_path") / kHostileName;
  fs::create_directories(dir);
  const CliRun g = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                 "--repetitions", "1", "--frames", "2", "--no-cache", "--json",
                                 (dir / "grid 'one'.json").string()});
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
  const CliRun r = run_cli_argv({"report", (dir / "grid 'one'.json").string(), "--out", (dir / "rep $(x)").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(dir / "rep $(x)" / "report.md"));
  CHECK_FALSE(fs::exists(dir / "PWNED"));
}

TEST_CASE("no shell: instruction counting passes a hostile cache folder to valgrind as data",
          "[hostile][no-shell][cli][slow]") {
  if (!program_runs("valgrind", "--version")) FAIL("valgrind is not installed (scripts/install-deps installs it)");
  const fs::path dir = hostile_scratch("callgrind_path");
  const fs::path cache = dir / kHostileName;
  const CliRun run = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                   "--repetitions", "1", "--frames", "1", "--metric", "instructions", "--cache-dir",
                                   cache.string(), "--json", (dir / "g.json").string()},
                                  dir);
  INFO(run.err);
#if defined(__SANITIZE_ADDRESS__)
  // valgrind cannot run an AddressSanitizer build: the run fails with one line, and still nothing
  // planted in the path runs.
  CHECK(run.exit_code == 2);
  CHECK(line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains("callgrind"));
#else
  REQUIRE(run.exit_code == 0);
  CHECK(fs::is_directory(cache));  // the cache was written at exactly that path
  CHECK(fs::exists(dir / "g.json"));
#endif
  for (const char* planted : {"PWNED", "PWNED2", "PWNED3"}) CHECK_FALSE(fs::exists(dir / planted));
}

TEST_CASE("no shell: report draws names that hold backquotes, gnuplot commands, newlines and quotes as text",
          "[hostile][no-shell][cli]") {
  const fs::path dir = hostile_scratch("report_names");
  const CliRun g = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                 "--repetitions", "1", "--frames", "2", "--no-cache", "--json",
                                 (dir / "grid.json").string()});
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
  // Names a results file could hold: a shell command in backquotes, a gnuplot `system` line after a
  // newline, a macro, quotes that would end a gnuplot string, and a Markdown row break.
  const std::string touch = "touch " + (dir / "PWNED").string();
  const std::vector<std::string> names = {
      "wall`" + touch + "`", "a\nsystem(\"" + touch + "2\")\nb", "x\" . system('" + touch + "3') . \"",
      "@macro \\\" `" + touch + "4` |col| <script>"};
  nlohmann::json grid = nlohmann::json::parse(file_bytes(dir / "grid.json"));
  grid["case"]["name"] = names[0];
  for (auto& cell : grid["cells"]) {
    cell["fracturer"] = names[1];
    cell["stress"] = names[2];
    nlohmann::json stages = nlohmann::json::object();
    for (auto& [stage, ms] : cell["stages_ms"].items()) stages[stage + names[3]] = ms;
    cell["stages_ms"] = stages;
    for (auto& sample : cell["samples"]) {
      nlohmann::json sample_stages = nlohmann::json::object();
      for (auto& [stage, ms] : sample["stages_ms"].items()) sample_stages[stage + names[3]] = ms;
      sample["stages_ms"] = sample_stages;
    }
  }
  put_file(dir / "hostile-grid.json", grid.dump());
  nlohmann::json accuracy = {{"kind", "accuracy"}, {"points", nlohmann::json::array()}};
  for (std::size_t i = 0; i < names.size(); ++i)
    accuracy["points"].push_back({{"family", "stress"}, {"case", names[(i + 1) % names.size()]}, {"algorithm", names[i]},
                                  {"knob", names[(i + 2) % names.size()]}, {"time_ms", 1.0 + static_cast<double>(i)},
                                  {"error", 1e-3 / (1.0 + static_cast<double>(i))}, {"pareto", i % 2 == 0}});
  put_file(dir / "hostile-accuracy.json", accuracy.dump());

  const fs::path out = dir / "report";
  const CliRun r = run_cli_argv({"report", (dir / "hostile-grid.json").string(), (dir / "hostile-accuracy.json").string(),
                                 "--out", out.string()},
                                dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* planted : {"PWNED", "PWNED2", "PWNED3", "PWNED4"}) CHECK_FALSE(fs::exists(dir / planted));
  // No script holds any of the names' text; every image was drawn.
  int scripts = 0, images = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string bytes = file_bytes(e.path());
    if (e.path().extension() == ".gp") {
      ++scripts;
      // File names are slugs of the names (letters, digits, '-', '.'); every other quoted
      // string is the script's own (fonts, colours, axis titles). Outside quotes nothing of the names
      // remains.
      CHECK(bytes.find('`') == std::string::npos);
      std::string unquoted;
      for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (bytes[i] != '"') {
          unquoted += bytes[i];
          continue;
        }
        const std::size_t end = bytes.find('"', i + 1);
        REQUIRE(end != std::string::npos);
        const std::string quoted = bytes.substr(i + 1, end - i - 1);
        INFO(quoted);
        const bool slug = quoted.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-.") == std::string::npos;
        if (!slug) {
          CHECK(quoted.find("touch") == std::string::npos);
          CHECK(quoted.find("system") == std::string::npos);
          CHECK(quoted.find('@') == std::string::npos);
        }
        i = end;
      }
      CHECK(unquoted.find("touch") == std::string::npos);
      CHECK(unquoted.find("system") == std::string::npos);
      CHECK(unquoted.find("macro") == std::string::npos);
    }
    if (e.path().extension() == ".png") {
      ++images;
      CHECK(bytes.size() > 1000);
    }
  }
  CHECK(scripts >= 3);  // heat map, stage bars, one Pareto chart per case
  CHECK(images == scripts);
  // The Markdown page keeps every table row on one line and opens no HTML element.
  const std::string page = file_bytes(out / "report.md");
  CHECK(page.find("<script>") == std::string::npos);
  CHECK(page.find("&lt;script&gt;") != std::string::npos);
  CHECK(page.find("\\|col\\|") != std::string::npos);
}
