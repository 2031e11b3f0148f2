// Hostile input, baselines: a baseline folder changes only through `grid --update-baseline`, and a case
// name is a file name that cannot lead a baseline out of its folder.

#include "harness/cases/case_loader.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <vector>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// Every file under `dir` with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    files[fs::relative(e.path(), dir).string()] = e.is_regular_file() ? file_bytes(e.path()) : std::string("<dir>");
  return files;
}

}  // namespace

TEST_CASE("baselines: no writer but grid --update-baseline writes into the baseline folder",
          "[hostile][baselines][cli]") {
  const fs::path dir = hostile_scratch("baselines");
  const fs::path baselines = dir / "results" / "baselines";
  fs::create_directories(baselines);
  const CliRun made = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                    "--repetitions", "1", "--frames", "2", "--no-cache", "--json", "grid.json"},
                                   dir);
  INFO(made.err);
  REQUIRE(made.exit_code == 0);
  put_file(baselines / "building.json", file_bytes(dir / "grid.json"));
  put_file(baselines / "building.csv", file_bytes(dir / "grid.csv"));
  REQUIRE(write_off(make_box({1, 1, 1}), dir / "cube.off").ok());
  const auto before = snapshot(dir / "results");

  const std::vector<std::string> tiny = {"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                         "--repetitions", "1", "--frames", "1", "--no-cache"};
  const auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<std::vector<std::string>> writers = {
      with(tiny, {"--json", "results/baselines/building.json"}),
      with(tiny, {"--json", "results/baselines/sub/../other.json"}),
      with(tiny, {"--junit", "results/baselines/junit.xml"}),
      with(tiny, {"--json", "results/../results/baselines/x.json"}),
      {"grid", "--case", "building", "--prefracture", "10", "--runtime", "5", "--repetitions", "1", "--frames", "1",
       "--cache-dir", "results/baselines/cache"},
      {"compare", "grid.json", "grid.json", "--markdown", "results/baselines/compare.md"},
      {"compare", "grid.json", "grid.json", "--junit", "results/baselines/building.csv"},
      {"merge", "grid.json", "--out", "results/baselines/building.json"},
      {"accuracy", "--case", "cantilever", "--family", "stress", "--slabs", "8", "--json", "results/baselines/acc.json"},
      {"stability", "--quick", "--hazard", "cut-along-edges", "--json", "results/baselines/stability.json"},
      {"report", "grid.json", "--out", "results/baselines"},
      {"report", "grid.json", "--out", "results/baselines/report"},
      {"report", "grid.json", "--out", "results"},
      {"fracture", "--mesh", "cube.off", "--fragments", "2", "--out", "results/baselines/frag"},
  };
  for (const auto& args : writers) {
    const CliRun run = run_cli_argv(args, dir);
    INFO(args[0] << " " << args.back() << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(line_count(run.err) == 1);
    CHECK(snapshot(dir / "results") == before);
  }
  // A symbolic link into the baseline folder is the baseline folder.
  fs::create_directory_symlink(baselines, dir / "linked");
  const CliRun linked = run_cli_argv(with(tiny, {"--json", "linked/building.json"}), dir);
  CHECK(linked.exit_code == 2);
  CHECK(snapshot(dir / "results") == before);

  // The update itself writes there.
  const CliRun update = run_cli_argv(with(tiny, {"--update-baseline"}), dir);
  INFO(update.err);
  REQUIRE(update.exit_code == 0);
  CHECK(snapshot(dir / "results") != before);
  CHECK(fs::exists(baselines / "building.json"));
  CHECK(partials_in(baselines) == 0);
}

TEST_CASE("baselines: a case name must be a file name", "[hostile][baselines]") {
  const std::vector<std::string> bad = {"../../evil", "a/b", "..", ".", ".hidden", "a\\\\b", "tab\\there",
                                        "x/../../y", "new\\nline", ""};
  for (const std::string& name : bad) {
    INFO(name);
    const Result<Case> c = parse_case(R"({"name": ")" + name + R"(", "mesh": {"box": {"size": [1, 1, 1]}}})",
                                      "case.json");
    REQUIRE_FALSE(c.ok());
    CHECK_THAT(c.error().message, Catch::Contains("name"));
  }
  for (const char* name : {"wall", "my-case_2", "bâtiment", "a.b"}) {
    INFO(name);
    CHECK(parse_case(R"({"name": ")" + std::string(name) + R"(", "mesh": {"box": {"size": [1, 1, 1]}}})", "case.json").ok());
  }
}

TEST_CASE("baselines: a case named to escape the baseline folder is refused before anything is written",
          "[hostile][baselines][cli]") {
  const fs::path dir = hostile_scratch("evil_name");
  fs::create_directories(dir / "work" / "results" / "baselines");
  put_file(dir / "work" / "evil.json",
           R"({"name": "../../evil", "mesh": {"box": {"size": [1, 1, 1], "center": [0, 0, 0.5]}},
               "prefracture": {"fracturer": "plane-slice", "fragments": 4}, "frames": 2,
               "grid": {"prefracture": [4], "runtime": [2]}})");
  const CliRun run = run_cli_argv({"grid", "--case", "evil.json", "--repetitions", "1", "--no-cache",
                                   "--update-baseline"},
                                  dir / "work");
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains("name"));
  CHECK_FALSE(fs::exists(dir / "evil.json"));
  CHECK(fs::is_empty(dir / "work" / "results" / "baselines"));
}
