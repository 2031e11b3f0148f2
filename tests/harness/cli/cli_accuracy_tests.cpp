// `shatterbench accuracy`: finite errors on a short run, the cantilever at round-off, bad input.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace {

using shatter::test::run_cli;
using shatter::test::slurp;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_accuracy_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("cli: accuracy short fracture run gives finite errors against the exact replay", "[cli][accuracy]") {
  const auto json = scratch("fracture") / "accuracy.json";
  const auto r = run_cli("accuracy --case wall --family fracture --fracturer plane-slice voronoi fem-lite "
                         "--fragments 5 --resolution 16 --repetitions 1 --json " + json.string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("## fracture") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(json));
  REQUIRE(j.at("kind") == "accuracy");
  // plane-slice, voronoi, and fem-lite at resolution 16 and at each documented cell budget (125, 512).
  REQUIRE(j.at("points").size() == 5);
  int budgets = 0;
  for (const auto& p : j.at("points"))
    if (p.at("knobs").contains("max_cells")) {
      CHECK(p.at("algorithm") == "fem-lite");
      CHECK_FALSE(p.at("knobs").contains("resolution"));
      ++budgets;
    }
  CHECK(budgets == 2);
  int front = 0;
  for (const auto& p : j.at("points")) {
    INFO(p.dump());
    REQUIRE(p.at("family") == "fracture");
    REQUIRE(p.at("error").is_number());
    CHECK(std::isfinite(p.at("error").get<double>()));
    CHECK(p.at("error").get<double>() < 1e-6);  // the fast kernels replay exactly, up to round-off
    CHECK(p.at("figures").at("volume_error").get<double>() < 1e-6);
    CHECK(p.at("figures").at("all_closed").get<bool>());
    CHECK(p.at("time_ms").get<double>() > 0.0);
    front += p.at("pareto").get<bool>() ? 1 : 0;
  }
  CHECK(front >= 1);
}

TEST_CASE("cli: accuracy stress errors of the cantilever are at round-off", "[cli][accuracy][stress]") {
  const auto json = scratch("cantilever") / "accuracy.json";
  const auto r = run_cli("accuracy --case cantilever --family stress --model von-mises tresca connection-count "
                         "--slabs 8 16 --repetitions 1 --json " + json.string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(slurp(json));
  int direct = 0;
  for (const auto& p : j.at("points")) {
    INFO(p.dump());
    REQUIRE(p.at("family") == "stress");
    REQUIRE(p.at("figures").at("reference") == "cantilever");
    if (p.at("algorithm") == "connection-count") {
      CHECK(p.at("error").is_null());  // no forces
      continue;
    }
    if (p.at("knobs").at("solver") != "default") continue;
    ++direct;
    CHECK(p.at("error").get<double>() < 1e-9);
    CHECK(p.at("figures").at("first_bond_match").get<bool>());  // the root bond carries the most
  }
  CHECK(direct == 4);  // 2 models x 2 slab counts
}

TEST_CASE("cli: accuracy fixed-fixed beam error falls with the slab count", "[cli][accuracy][stress]") {
  const auto json = scratch("fixed") / "a.json";
  const auto r = run_cli("accuracy --case fixed-beam --family stress --model von-mises --slabs 8 16 --repetitions 1 "
                         "--json " + json.string());
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(slurp(json));
  double e8 = 0, e16 = 0;
  for (const auto& p : j.at("points"))
    if (p.at("knobs").at("solver") == "default")
      (p.at("knobs").at("slabs") == 8 ? e8 : e16) = p.at("error").get<double>();
  CHECK(e8 == Approx(0.0313).epsilon(0.05));  // mid-span 2 / n^2 (docs/stress.md)
  CHECK(e16 < e8 / 3.0);
}

TEST_CASE("cli: accuracy refuses bad input with exit 2, one line, and writes nothing", "[cli][accuracy]") {
  const auto dir = scratch("bad");
  const auto json = dir / "a.json";
  const std::string out = " --repetitions 1 --json " + json.string();
  const std::pair<std::string, std::string> cases[] = {
      {"accuracy --case no-such-case" + out, "no-such-case"},
      {"accuracy --case cantilever --model no-such-model" + out, "--model"},
      {"accuracy --case wall --fracturer no-such-algo" + out, "--fracturer"},
      {"accuracy --case wall --fracturer cgal-clip" + out, "--fracturer"},
      {"accuracy --case wall --family physics" + out, "--family"},
      {"accuracy --case cantilever --slabs 7" + out, "--slabs"},
      {"accuracy --case wall --resolution 1" + out, "--resolution"},
      {"accuracy --case wall --repetitions 0 --json " + json.string(), "--repetitions"},
      {"accuracy --case wall --no-such-flag" + out, "no-such-flag"},
  };
  for (const auto& [args, words] : cases) {
    INFO(args);
    const auto r = run_cli(args);
    CHECK(r.exit_code == 2);
    CHECK(shatter::test::line_count(r.err) == 1);
    CHECK(r.err.find(words) != std::string::npos);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(json));
  }
}

TEST_CASE("cli: accuracy colliders family measures the volume a vertex budget and the inner points cut off", "[cli][accuracy][colliders]") {
  const auto json = scratch("colliders") / "a.json";
  const auto r = run_cli("accuracy --case elephant --family colliders --fragments 5 --vertex-budget 0 8 32 "
                         "--repetitions 1 --json " + json.string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("## colliders") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(json));
  REQUIRE(j.at("points").size() == 4);  // the three budgets and the exact path
  std::map<int, double> loss;
  double every_point_loss = -1.0;
  double every_point_mean = 0.0;
  double outer_mean = 0.0;
  for (const auto& p : j.at("points")) {
    INFO(p.dump());
    REQUIRE(p.at("family") == "colliders");
    const int budget = p.at("knobs").at("vertex_budget").get<int>();
    const double mean_points = p.at("figures").at("mean_points").get<double>();
    if (p.at("knobs").at("drop_inner_points").get<bool>()) {
      loss[budget] = p.at("error").get<double>();
      if (budget == 0) outer_mean = mean_points;
    } else {
      every_point_loss = p.at("error").get<double>();
      every_point_mean = mean_points;
    }
    CHECK(p.at("figures").at("pieces").get<int>() >= 5);
    if (budget > 0) CHECK(mean_points <= budget);
    CHECK(p.at("time_ms").get<double>() > 0.0);
  }
  CHECK(every_point_loss == 0.0);  // every point: the hull itself
  CHECK(loss.at(0) <= 1e-12);      // the points that cannot be corners: the same hull to round-off
  CHECK(outer_mean < every_point_mean);
  // The elephant's pieces have hundreds of points: 8 of them cut off much, 32 less, never all.
  CHECK(loss.at(8) > loss.at(32));
  CHECK(loss.at(32) > 0.0);
  CHECK(loss.at(8) < 1.0);
}

TEST_CASE("cli: accuracy refuses a vertex budget below 4 and an unknown family", "[cli][accuracy][colliders]") {
  const auto budget = run_cli("accuracy --case wall --family colliders --vertex-budget 3");
  CHECK(budget.exit_code == 2);
  CHECK(budget.err.find("--vertex-budget") != std::string::npos);
  CHECK(budget.out.empty());
  const auto family = run_cli("accuracy --case wall --family hulls");
  CHECK(family.exit_code == 2);
  CHECK(family.err.find("fracture, stress, colliders or cascade") != std::string::npos);
}

TEST_CASE("cli: accuracy cascade family sets each model's cascade against the exact one", "[cli][accuracy][cascade]") {
  const auto json = scratch("cascade") / "a.json";
  const auto r = run_cli("accuracy --case wall --family cascade --repetitions 1 --json " + json.string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("## cascade") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(json));
  // tresca, von-mises, and each windowed model at its default, at hops 1, 2, 4 and 8 and at exact_start
  // 0 and 1.
  REQUIRE(j.at("points").size() == 16);
  std::map<std::string, double> error;
  for (const auto& p : j.at("points")) {
    INFO(p.dump());
    REQUIRE(p.at("family") == "cascade");
    const auto& f = p.at("figures");
    REQUIRE_FALSE(f.contains("failed"));
    CHECK(f.at("reference_rounds").get<int>() >= 2);  // the scaled strengths make a real cascade
    CHECK(f.at("reference_broken").get<int>() > f.at("hole").get<int>());
    CHECK(p.at("time_ms").get<double>() > 0.0);
    const double e = p.at("error").get<double>();
    CHECK(e == std::max(f.at("broken_mismatch").get<double>(), f.at("falling_mismatch").get<double>()));
    error[p.at("algorithm").get<std::string>() + " " + p.at("knob").get<std::string>()] = e;
  }
  // The exact models are the reference's own cascade, and so is a window over the whole wall.
  CHECK(error.at("von-mises default") == 0.0);
  CHECK(error.at("tresca default") == 0.0);
  CHECK(error.at("von-mises-local hops=8") == 0.0);
  // A window of one bond holds the wall up where the exact cascade goes on: the error is measured.
  CHECK(error.at("von-mises-local hops=1") > 0.1);
  CHECK(error.at("tresca-local hops=1") > 0.1);
}
