// The `stress` command: beam theory through the whole chain (case file, explicit cuts, support graph,
// rigid-body-spring solve, JSON), and the exit-2 contract on bad cases.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

fs::path write_case(const std::string& name, const nlohmann::json& j) {
  const fs::path dir = fs::temp_directory_path() / "shatter_cli_tests" / "stress";
  fs::create_directories(dir);
  const fs::path p = dir / (name + ".json");
  std::ofstream(p) << j.dump(2);
  return p;
}

nlohmann::json small_cantilever() {
  return nlohmann::json::parse(R"({
    "mesh": {"box": {"size": [2, 0.2, 0.3], "center": [1, 0, 0]}},
    "material": {"density": 2000},
    "anchors": [{"box": {"min": [-1, -1, -1], "max": [0.001, 1, 1]}}],
    "prefracture": {"planes": [{"point": [0.5, 0, 0], "normal": [1, 0, 0]},
                               {"point": [1.0, 0, 0], "normal": [1, 0, 0]},
                               {"point": [1.5, 0, 0], "normal": [1, 0, 0]}]}
  })");
}

}  // namespace

TEST_CASE("cli: stress on the built-in cantilever matches beam theory at every bond", "[cli][stress]") {
  for (const char* model : {"von-mises", "tresca"}) {
    INFO(model);
    const auto run = test::run_cli(std::string("stress --case cantilever --model ") + model + " --json");
    REQUIRE(run.exit_code == 0);
    const auto j = nlohmann::json::parse(run.out);
    CHECK(j.at("model") == model);
    const double rho = 2400, g = 9.81, b = 0.5, h = 0.5, length = 4.0;
    const auto& bonds = j.at("bonds");
    REQUIRE(bonds.size() == 7);
    for (const auto& bond : bonds) {
      const double x = bond.at("centroid")[0];
      const double moment = rho * g * b * h * (length - x) * (length - x) / 2;
      const double sigma = moment * (h / 2) / (b * h * h * h / 12);
      CHECK(bond.at("bending_moment").get<double>() == Approx(moment).epsilon(1e-9));
      CHECK(bond.at("sigma").get<double>() == Approx(sigma).epsilon(1e-9));
      CHECK(bond.at("shear_force").get<double>() == Approx(rho * g * b * h * (length - x)).epsilon(1e-9));
      CHECK_FALSE(bond.at("broken").get<bool>());
    }
    CHECK(j.at("falling_clusters").empty());
  }
}

TEST_CASE("cli: a weak cantilever breaks at the root and drops the span", "[cli][stress]") {
  nlohmann::json c = small_cantilever();
  // Just below the root bond's peak stress M c / I (the next bond carries less than half of it).
  const double moment = 2000 * 9.81 * 0.2 * 0.3 * 1.5 * 1.5 / 2;
  const double root_sigma = moment * 0.15 / (0.2 * 0.3 * 0.3 * 0.3 / 12);
  c["material"]["tensile_strength"] = 0.95 * root_sigma;
  const auto run = test::run_cli("stress --json --case " + write_case("weak", c).string());
  REQUIRE(run.exit_code == 0);
  const auto j = nlohmann::json::parse(run.out);
  REQUIRE(j.at("break_order").size() >= 1);
  const auto& first = j.at("break_order")[0];
  REQUIRE(first.size() == 1);
  const int root = first[0];
  CHECK(j.at("bonds")[root].at("centroid")[0].get<double>() == Approx(0.5));
  REQUIRE(j.at("falling_clusters").size() == 1);
  CHECK(j.at("falling_clusters")[0].size() == 3);
}

TEST_CASE("cli: stress refuses bad cases with one line naming the key", "[cli][stress]") {
  struct BadCase {
    const char* name;
    nlohmann::json patch;
    const char* mentions;
  };
  nlohmann::json unknown = small_cantilever();
  unknown["materiel"] = nlohmann::json::object();
  nlohmann::json negative = small_cantilever();
  negative["material"]["density"] = -3;
  nlohmann::json nowhere = small_cantilever();
  nowhere["anchors"] = nlohmann::json::parse(R"([{"box": {"min": [10, 10, 10], "max": [11, 11, 11]}}])");
  nlohmann::json nested = small_cantilever();
  nested["material"]["strength"] = 3;
  const std::vector<std::pair<nlohmann::json, std::string>> cases = {
      {unknown, "materiel"}, {negative, "material.density"}, {nowhere, "anchors[0]"}, {nested, "material.strength"}};
  int i = 0;
  for (const auto& [json, mentions] : cases) {
    INFO(mentions);
    const auto run = test::run_cli("stress --case " + write_case("bad" + std::to_string(i++), json).string());
    CHECK(run.exit_code == 2);
    CHECK(test::line_count(run.err) == 1);
    CHECK_THAT(run.err, Catch::Contains(mentions));
    CHECK(run.out.empty());
  }
  const auto unknown_model = test::run_cli("stress --case cantilever --model nope");
  CHECK(unknown_model.exit_code == 2);
  CHECK_THAT(unknown_model.err, Catch::Contains("von-mises"));
  const auto unknown_case = test::run_cli("stress --case no-such-case");
  CHECK(unknown_case.exit_code == 2);
  CHECK(test::line_count(unknown_case.err) == 1);
}

TEST_CASE("cli: list shows fracturers, stress models and built-in cases", "[cli]") {
  const auto run = test::run_cli("list");
  REQUIRE(run.exit_code == 0);
  for (const char* name : {"plane-slice", "cgal-clip", "connection-count", "tresca", "von-mises", "cantilever",
                           "column", "fixed-beam", "wall", "tower"})
    CHECK_THAT(run.out, Catch::Contains(name));
}
