// Plugins from outside the tree (plugin_api.h, harness/plugins/plugin_loader.h): libraries built from
// tests/plugin_fixtures/ against the headers alone, loaded by the shatterbench binary with --plugin
// and SHATTERBENCH_PLUGIN_PATH. "test-shards" is plane-slice called through the host's symbols, so
// its fragments must be plane-slice's; the refusals must be one line on stderr with exit code 2.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

std::string plugin(const std::string& name) {
  const fs::path path = fs::path(SHATTER_TEST_PLUGIN_DIR) / (name + "_plugin.so");
  REQUIRE(fs::exists(path));  // built with the tests: missing means a broken build, not a pass
  return path.string();
}

std::string elephant() {
  const fs::path path = fs::path(SHATTER_SOURCE_DIR) / "data" / "meshes" / "elephant.off";
  REQUIRE(fs::exists(path));
  return path.string();
}

/// Sets an environment variable for the life of the object.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

void check_refused(const test::CliRun& run, const std::string& says) {
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(test::line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains(says));
}

}  // namespace

TEST_CASE("plugins: a plugin's fracturer and stress model are listed and fracture as the host's code does",
          "[plugins]") {
  const test::CliRun list = test::run_cli_argv({"--plugin", plugin("shards"), "list"});
  REQUIRE(list.exit_code == 0);
  CHECK_THAT(list.out, Catch::Contains("test-shards") && Catch::Contains("test-count") &&
                           Catch::Contains("plane-slice"));
  // The plugin's two names say where they came from; the built-ins say nothing.
  const std::string from = "\n    from plugin " + plugin("shards") + "\n";
  std::size_t origins = 0;
  for (std::size_t at = list.out.find(from); at != std::string::npos; at = list.out.find(from, at + 1)) ++origins;
  CHECK(origins == 2);
  CHECK(list.out.find("test-shards") < list.out.find(from));
  // Without the plugin the names are unknown.
  check_refused(test::run_cli_argv({"fracture", "--mesh", elephant(), "--algo", "test-shards"}), "test-shards");

  const test::CliRun shards =
      test::run_cli_argv({"fracture", "--plugin", plugin("shards"), "--mesh", elephant(), "--algo", "test-shards",
                          "--fragments", "7", "--seed", "5"});
  REQUIRE(shards.exit_code == 0);
  const test::CliRun builtin = test::run_cli_argv(
      {"fracture", "--mesh", elephant(), "--algo", "plane-slice", "--fragments", "7", "--seed", "5"});
  REQUIRE(builtin.exit_code == 0);
  const auto a = nlohmann::json::parse(shards.out);
  const auto b = nlohmann::json::parse(builtin.out);
  CHECK(a["algorithm"] == "test-shards");
  CHECK(a["fragments"] == b["fragments"]);
  CHECK(a["metrics"]["all_closed"] == true);
  CHECK(a["metrics"]["volume_error"] == b["metrics"]["volume_error"]);
  CHECK(a["metrics"]["min_fragment_volume"] == b["metrics"]["min_fragment_volume"]);
}

TEST_CASE("plugins: SHATTERBENCH_PLUGIN_PATH loads files and folders, and a grid runs the plugin's algorithms",
          "[plugins]") {
  const fs::path dir = fs::temp_directory_path() / ("shatter_plugin_path_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy_file(plugin("shards"), dir / "shards_plugin.so", fs::copy_options::overwrite_existing);
  {
    const ScopedEnv env("SHATTERBENCH_PLUGIN_PATH", ":" + dir.string() + ":");
    const test::CliRun grid = test::run_cli_argv({"grid", "--case", "building", "--fracturer", "test-shards",
                                                  "--stress", "test-count", "--prefracture", "10", "--runtime", "5",
                                                  "--repetitions", "1", "--frames", "3", "--no-cache"});
    CHECK(grid.exit_code == 0);
    CHECK_THAT(grid.out, Catch::Contains("10"));
  }
  {
    const ScopedEnv env("SHATTERBENCH_PLUGIN_PATH", (dir / "missing").string());
    check_refused(test::run_cli_argv({"list"}), "does not exist");
  }
  fs::remove_all(dir);
}

TEST_CASE("plugins: refused with one line naming the plugin", "[plugins]") {
  SECTION("built against another version") {
    const std::string path = plugin("wrong_abi");
    // The ABI is read first: a descriptor of another ABI is not read further (its version is a pointer).
    check_refused(test::run_cli_argv({"--plugin", path, "list"}), "plugin " + path + ": built for plugin ABI 999");
  }
  SECTION("a name two plugins register: both paths named") {
    const std::string first = plugin("shards");
    const std::string second = plugin("shards_again");
    check_refused(test::run_cli_argv({"--plugin", first, "--plugin", second, "list"}),
                  "plugin " + second + ": fracturer 'test-shards' is already registered by " + first);
  }
  SECTION("a built-in's name is taken too") {
    // Loaded twice under one path: the second registration finds the first's names.
    const std::string path = plugin("shards");
    check_refused(test::run_cli_argv({"--plugin", path, "--plugin", path, "list"}), "already registered by " + path);
  }
  SECTION("a name registered twice by one plugin built with assertions on") {
    const std::string path = plugin("careless");
    check_refused(test::run_cli_argv({"--plugin", path, "list"}), "plugin " + path + ": fracturer 'test-twice' is registered twice");
  }
  SECTION("not a plugin, not a library, no path") {
    check_refused(test::run_cli_argv({"--plugin", SHATTER_CLI, "list"}), "cannot load");
    check_refused(test::run_cli_argv({"--plugin", "/nonexistent/x.so", "list"}), "cannot load");
    check_refused(test::run_cli_argv({"list", "--plugin"}), "--plugin needs the path");
  }
}

TEST_CASE("plugins: a plugin that throws or crashes inside a fracture fails only its cell", "[plugins]") {
  const std::string faulty = plugin("faulty");
  const std::vector<std::string> cell = {"--case", "building", "--prefracture", "10", "--runtime", "5",
                                         "--repetitions", "1", "--frames", "3", "--no-cache"};
  const auto grid = [&](const std::string& fracturer, bool timeout) {
    std::vector<std::string> args = {"--plugin", faulty, "grid", "--fracturer", fracturer};
    args.insert(args.end(), cell.begin(), cell.end());
    if (timeout) args.insert(args.end(), {"--timeout", "60"});
    return test::run_cli_argv(args);
  };
  SECTION("an exception, without and with --timeout") {
    for (const bool timeout : {false, true}) {
      INFO("timeout " << timeout);
      const test::CliRun run = grid("test-throws", timeout);
      CHECK(run.exit_code == 1);  // the gate fails: the cell failed; the grid itself ran to the end
      CHECK_THAT(run.out + run.err, Catch::Contains("10 x 5"));
      CHECK_THAT(run.out + run.err, Catch::Contains("threw: test-throws always throws"));
    }
  }
  SECTION("a crash, with --timeout") {
    const test::CliRun run = grid("test-crashes", true);
    CHECK(run.exit_code == 1);
    CHECK_THAT(run.out + run.err, Catch::Contains("crashed"));
  }
  SECTION("a crash, without --timeout: the run ends as a game would, and leaves no result behind") {
    const fs::path json = fs::temp_directory_path() / ("shatter_plugin_crash_" + std::to_string(::getpid()) + ".json");
    fs::remove(json);
    std::vector<std::string> args = {"--plugin", faulty, "grid", "--fracturer", "test-crashes", "--json", json.string()};
    args.insert(args.end(), cell.begin(), cell.end());
    const test::CliRun run = test::run_cli_argv(args);
    CHECK(run.exit_code != 0);  // killed by the signal (a sanitizer build reports it and exits 1)
    CHECK_FALSE(fs::exists(json));
  }
}
