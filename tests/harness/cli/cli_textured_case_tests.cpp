// The textured built-in cases run through the grid like any other case: their fragments carry
// attributes through pre-fracture and runtime fracture, and every cell's checks hold.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace {

using shatter::test::run_cli;
using shatter::test::slurp;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_textured_case_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("cli: the textured cases run through the grid, runtime fracture included", "[cli][grid][attributes]") {
  for (const std::string name : {"wall-textured", "textured-box"}) {
    INFO(name);
    const auto json = scratch(name) / "grid.json";
    // 12 frames: past the impact at frame 10, so the runtime fracture of the hit piece runs.
    const auto r = run_cli("grid --case " + name + " --prefracture 10 --runtime 5 --repetitions 1 --frames 12 "
                           "--no-cache --json " + json.string());
    INFO(r.err);
    REQUIRE((r.exit_code == 0 || r.exit_code == 1));  // 1: a cell over the budget on a slow machine
    const auto j = nlohmann::json::parse(slurp(json));
    REQUIRE(j.at("cells").size() == 1);
    const auto& cell = j.at("cells")[0];
    REQUIRE_FALSE(cell.contains("failed"));
    CHECK(cell.at("error").at("prefracture").at("volume_error").get<double>() < 1e-9);
    CHECK(cell.at("stages_run").size() >= 6);
  }
}
