// The proof that registries are open: a fracturer and a stress model defined only in tests/ are
// registered with one line each and then get every command through run_cli, with no other edit.

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "algorithms/registry/registries.h"
#include "harness/cli/run_cli.h"
#include "tests/registry/user_plugins.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

/// The built-ins plus the two test plugins: the one registration line each.
Registries user_registries() {
  Registries r;
  register_all(r);
  test::register_parallel_planes(r.fracturers);
  test::register_scaled_von_mises(r.stress_models);
  return r;
}

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("shatter_user_plugin_tests_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

/// Runs run_cli(`args`) with `registries` in a forked child, its stdout and stderr captured.
test::CliRun run_in_process(const std::vector<std::string>& args, const Registries& registries) {
  static int counter = 0;
  const fs::path out = scratch() / ("out" + std::to_string(counter));
  const fs::path err = scratch() / ("err" + std::to_string(counter++));
  std::cout.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, STDOUT_FILENO);
    ::dup2(e, STDERR_FILENO);
    std::vector<std::string> words = {"shatterbench"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const int code = run_cli(static_cast<int>(words.size()), argv.data(), registries);
    std::cout.flush();
    std::fflush(nullptr);
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return test::collect_run(status, out, err);
}

/// A 4 x 1 x 1 m concrete bar anchored at one end and hit at the other, cut and judged by the test plugins
/// with settings.
fs::path write_bar_case() {
  const fs::path path = scratch() / "bar.json";
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs(R"({
  "name": "bar",
  "mesh": {"box": {"size": [4, 1, 1], "center": [2, 0, 0.5]}},
  "anchors": [{"box": {"min": [-1, -1, -1], "max": [0.001, 1, 2]}}],
  "prefracture": {"fracturer": "parallel-planes", "fragments": 4, "seed": 1, "settings": {"axis": 0}},
  "impacts": [{"frame": 1, "point": [4, 0, 0.5], "direction": [-1, 0, 0], "impulse": 1000, "radius": 0.5}],
  "runtime": {"fracturer": "parallel-planes", "fragments": 2, "settings": {"axis": 2}},
  "stress": {"model": "scaled-von-mises", "settings": {"factor": 2}},
  "frames": 3,
  "grid": {"prefracture": [4], "runtime": [2]}
})",
             f);
  std::fclose(f);
  return path;
}

}  // namespace

TEST_CASE("registry: a plugin from outside the library gets list, table, grid, accuracy and stability",
          "[registry][cli]") {
  const Registries registries = user_registries();
  const fs::path bar = write_bar_case();

  SECTION("list names the plugins and their settings") {
    const test::CliRun r = run_in_process({"list"}, registries);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("parallel-planes"));
    CHECK_THAT(r.out, Catch::Contains("scaled-von-mises"));
    CHECK_THAT(r.out, Catch::Contains("settings.axis"));
    CHECK_THAT(r.out, Catch::Contains("settings.factor"));
    CHECK_THAT(r.out, Catch::Contains("settings.resolution"));  // the built-ins are there too
  }
  SECTION("table fractures with it") {
    const fs::path mesh = scratch() / "cube.off";
    REQUIRE(write_off(make_box(Vec3(1, 1, 1)), mesh).ok());
    const test::CliRun r = run_in_process(
        {"table", "--mesh", mesh.string(), "--algo", "parallel-planes", "--fragments", "4", "--repetitions", "1"},
        registries);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("parallel-planes"));
  }
  SECTION("grid runs the case's plugins with the case's settings") {
    const fs::path json = scratch() / "grid.json";
    const test::CliRun r = run_in_process(
        {"grid", "--case", bar.string(), "--repetitions", "1", "--no-cache", "--json", json.string()}, registries);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const nlohmann::json grid = nlohmann::json::parse(test::slurp(json));
    REQUIRE(grid["cells"].size() == 1);
    CHECK(grid["cells"][0]["fracturer"] == "parallel-planes");
    CHECK(grid["cells"][0]["stress"] == "scaled-von-mises");
  }
  SECTION("a bad setting of a user plugin is bad input naming the key") {
    const fs::path bad = scratch() / "bad.json";
    std::string text = test::slurp(bar);
    text.replace(text.find("\"factor\": 2"), 11, "\"factor\": 0");
    std::FILE* f = std::fopen(bad.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    const test::CliRun r = run_in_process({"grid", "--case", bad.string(), "--repetitions", "1"}, registries);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("scaled-von-mises: settings.factor: must be in (0, 1000], got 0"));
  }
  SECTION("accuracy replays its cut plan exactly") {
    const fs::path json = scratch() / "accuracy.json";
    const test::CliRun r =
        run_in_process({"accuracy", "--case", bar.string(), "--family", "fracture", "--fracturer", "parallel-planes",
                        "--fragments", "4", "--repetitions", "1", "--json", json.string()},
                       registries);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const nlohmann::json accuracy = nlohmann::json::parse(test::slurp(json));
    REQUIRE(accuracy["points"].size() == 1);
    const nlohmann::json& figures = accuracy["points"][0]["figures"];
    INFO(figures.dump());
    REQUIRE(figures.contains("replay_volume_error"));
    const double error = figures["replay_volume_error"].get<double>();
    CHECK(std::isfinite(error));
    CHECK(error < 1e-9);
    CHECK(figures["replay_fragments"] == 4);
  }
  SECTION("stability runs its hazards") {
    const test::CliRun r = run_in_process({"stability", "--algo", "parallel-planes", "--model", "scaled-von-mises",
                                           "--quick", "--hazard", "inverted-orientation", "--hazard", "thin-plate",
                                           "--hazard", "zero-gravity", "--hazard", "no-anchor"},
                                          registries);
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("parallel-planes"));
    CHECK_THAT(r.out, Catch::Contains("scaled-von-mises"));
  }
}
