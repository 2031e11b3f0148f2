// `--set NAME.KEY=VALUE` (harness/plugins/setting_overrides.h): a plugin setting from the command line
// reaches the algorithm wherever the command creates it, and a bad one is one line and exit 2.

#include "tests/support/cli_runner.h"
#include "tests/support/mesh_fixtures.h"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

using namespace shatter::test;

namespace {

/// The "fragments" figure of a `fracture` run's JSON.
int fragment_count(const CliRun& run) {
  REQUIRE(run.exit_code == 0);
  return nlohmann::json::parse(run.out).at("fragments").get<int>();
}

}  // namespace

TEST_CASE("cli --set: a setting changes the algorithm it names, and only that one", "[cli][settings]") {
  if (!have_meshes()) return;
  const std::string mesh = (mesh_dir() / "elephant.off").string();
  const std::vector<std::string> fem = {"fracture", "--mesh", mesh, "--algo", "fem-lite", "--fragments", "10"};
  const int by_default = fragment_count(run_cli_argv(fem));
  std::vector<std::string> coarse = {"--set", "fem-lite.resolution=4"};
  coarse.insert(coarse.end(), fem.begin(), fem.end());
  const int coarse_count = fragment_count(run_cli_argv(coarse));
  // A grid of 4 cells along the elephant has room for fewer cracks than the default 16.
  CHECK(coarse_count < by_default);
  // The same, written as --set=...; and a setting of another algorithm leaves fem-lite as it was.
  std::vector<std::string> joined = {"--set=fem-lite.resolution=4"};
  joined.insert(joined.end(), fem.begin(), fem.end());
  CHECK(fragment_count(run_cli_argv(joined)) == coarse_count);
  std::vector<std::string> other = {"--set", "voronoi.leaf_cells=4"};
  other.insert(other.end(), fem.begin(), fem.end());
  CHECK(fragment_count(run_cli_argv(other)) == by_default);
}

TEST_CASE("cli --set: a malformed, unknown or out-of-range setting is one line and exit 2", "[cli][settings]") {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"fem-lite.resolution", "no '='"},
      {"fem-lite=4", "no algorithm name"},
      {"fem-lite.Resolution=4", "snake_case"},
      {"nothing.resolution=4", "no fracturer or stress model is named 'nothing'"},
      {"fem-lite.bogus=4", "settings.bogus: unknown key"},
      {"fem-lite.resolution=1", "settings.resolution"},
      {"fem-lite.resolution=nan", "settings.resolution"},
      {"von-mises.cg_only=maybe", "settings.cg_only"},
  };
  for (const auto& [value, says] : bad) {
    const CliRun run = run_cli_argv({"--set", value, "list"});
    INFO(value << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(line_count(run.err) == 1);
    CHECK_THAT(run.err, Catch::Contains(says));
    CHECK(run.out.empty());
  }
  const CliRun twice = run_cli_argv({"--set", "fem-lite.resolution=4", "--set", "fem-lite.resolution=8", "list"});
  CHECK(twice.exit_code == 2);
  CHECK_THAT(twice.err, Catch::Contains("set twice"));
  const CliRun missing = run_cli_argv({"list", "--set"});
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.err, Catch::Contains("--set needs NAME.KEY=VALUE"));
}

TEST_CASE("cli --set: SHATTERBENCH_SET carries settings to a child run, and a flag overrides it", "[cli][settings]") {
  if (!have_meshes()) return;
  const std::string mesh = (mesh_dir() / "elephant.off").string();
  const std::vector<std::string> fem = {"fracture", "--mesh", mesh, "--algo", "fem-lite", "--fragments", "10"};
  std::vector<std::string> coarse = {"--set", "fem-lite.resolution=4"};
  coarse.insert(coarse.end(), fem.begin(), fem.end());
  const int coarse_count = fragment_count(run_cli_argv(coarse));
  const int by_default = fragment_count(run_cli_argv(fem));
  REQUIRE(coarse_count != by_default);
  // As grid --metric instructions' child inherits it: the variable alone sets the key.
  ::setenv("SHATTERBENCH_SET", "fem-lite.resolution=4\n", 1);
  CHECK(fragment_count(run_cli_argv(fem)) == coarse_count);
  std::vector<std::string> back = {"--set", "fem-lite.resolution=16"};
  back.insert(back.end(), fem.begin(), fem.end());
  CHECK(fragment_count(run_cli_argv(back)) == by_default);
  ::setenv("SHATTERBENCH_SET", "fem-lite.resolution\n", 1);
  const CliRun bad = run_cli_argv({"list"});
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("SHATTERBENCH_SET: --set fem-lite.resolution"));
  ::unsetenv("SHATTERBENCH_SET");
}
