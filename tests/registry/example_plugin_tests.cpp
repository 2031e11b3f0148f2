// A plugin from examples/ ("slabs", examples/minimal_plugin, built with the tests as its own project
// builds it) takes part in `stability` and `accuracy` as a built-in does. It cuts only where it
// chooses (no Fracturer::plane_cutting), so the plane hazards pre-cut the cube with a fracturer that
// declares the capability and slabs fractures each piece, as for a built-in without it; it states its
// cut plan, so accuracy replays it with the exact reference.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using shatter::test::run_cli_argv;

namespace {

std::string slabs_plugin() {
  const fs::path path = fs::path(SHATTER_TEST_PLUGIN_DIR) / "example_slabs_plugin.so";
  REQUIRE(fs::exists(path));  // built with the tests: missing means a broken build, not a pass
  return path.string();
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shatter_example_plugin_" + name + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("example plugin: slabs runs the stability hazards as a built-in", "[plugins][stability][cli]") {
  const fs::path dir = scratch("stability");
  const fs::path json = dir / "stability.json";
  const auto r = run_cli_argv({"--plugin", slabs_plugin(), "stability", "--quick", "--algo", "slabs", "--hazard",
                               "cut-along-edges", "--hazard", "cut-containing-faces", "--hazard", "scale-1e4",
                               "--hazard", "refracture", "--json", json.string()});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json doc = nlohmann::json::parse(shatter::test::slurp(json));
  REQUIRE(doc.at("results").size() == 4);
  for (const auto& h : doc.at("results")) {
    INFO(h.dump());
    CHECK(h.at("algorithm") == "slabs");
    CHECK(h.at("kind") == "fracture");
    CHECK(h.at("outcome") == "VALID");
    CHECK(h.at("worst_error").get<double>() < 1e-6);
  }
  // A plane hazard: the exact cut's two halves of the cube, each fractured into slabs by the plugin.
  for (const auto& h : doc.at("results"))
    if (h.at("hazard") == "cut-along-edges") CHECK(h.at("fragments").get<int>() > 2);
  fs::remove_all(dir);
}

TEST_CASE("example plugin: slabs has accuracy rows against the exact replay as a built-in", "[plugins][accuracy][cli]") {
  const fs::path dir = scratch("accuracy");
  const fs::path json = dir / "accuracy.json";
  const auto r = run_cli_argv({"--plugin", slabs_plugin(), "accuracy", "--case", "wall", "--family", "fracture",
                               "--fracturer", "slabs", "voronoi", "--fragments", "5", "--repetitions", "1", "--json",
                               json.string()});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json doc = nlohmann::json::parse(shatter::test::slurp(json));
  int slabs = 0;
  for (const auto& p : doc.at("points")) {
    INFO(p.dump());
    REQUIRE(p.at("family") == "fracture");
    const auto& f = p.at("figures");
    REQUIRE_FALSE(f.contains("failed"));
    REQUIRE_FALSE(f.contains("failed_checks"));
    CHECK(f.at("all_closed").get<bool>());
    CHECK(f.at("volume_error").get<double>() < 1e-6);
    CHECK(f.at("replay_fragments").get<int>() >= 5);
    CHECK(std::isfinite(p.at("error").get<double>()));
    CHECK(p.at("error").get<double>() < 1e-6);  // the slicing kernel replays exactly, up to round-off
    CHECK(p.at("time_ms").get<double>() > 0.0);
    if (p.at("algorithm") == "slabs") ++slabs;
  }
  CHECK(slabs == 1);
  fs::remove_all(dir);
}
