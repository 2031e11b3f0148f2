/// The stability battery: isolation, the verdicts of a few hazards, and the CLI command in quick form.

#include "harness/stability/fracture_hazards.h"
#include "harness/process/isolated_run.h"
#include "harness/process/isolated_run.h"
#include "tests/support/builtin_registries.h"
#include "harness/stability/stability_battery.h"
#include "tests/support/builtin_registries.h"
#include "harness/stability/stress_hazards.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <thread>

using namespace shatter;
using shatter::test::run_cli;

namespace {

const FractureHazard& find_fracture_hazard(const std::vector<FractureHazard>& all, const std::string& name) {
  const auto it = std::find_if(all.begin(), all.end(), [&](const FractureHazard& h) { return h.name == name; });
  REQUIRE(it != all.end());
  return *it;
}

}  // namespace

TEST_CASE("stability: an isolated run hands back its output, a crash and a hang become verdicts", "[stability]") {
  const IsolatedRun ok = run_isolated([] { return std::string("done"); }, 10.0);
  CHECK(ok.end == IsolatedRun::End::finished);
  CHECK(ok.output == "done");

  const IsolatedRun crash = run_isolated([]() -> std::string { std::raise(SIGSEGV); return "never"; }, 10.0);
  CHECK(crash.end == IsolatedRun::End::crashed);
  CHECK(crash.detail.find("signal 11") != std::string::npos);

  const IsolatedRun hang = run_isolated([] {
    std::this_thread::sleep_for(std::chrono::seconds(30));
    return std::string("late");
  }, 0.3);
  CHECK(hang.end == IsolatedRun::End::timed_out);
  CHECK(hang.time_ms < 10000.0);
}

TEST_CASE("stability: plane-slice cuts through vertices, along edges and in face planes validly", "[stability]") {
  const std::vector<FractureHazard> all = fracture_hazards(true);
  for (const char* name : {"cut-through-vertices", "cut-along-edges", "cut-containing-faces", "grazing-planes",
                           "nearly-parallel-planes"}) {
    const HazardResult r = run_fracture_hazard(find_fracture_hazard(all, name), "plane-slice", test::builtin_registries());
    INFO(name << ": " << outcome_tag(r.outcome) << " " << r.detail);
    CHECK(r.outcome == HazardOutcome::valid);
    CHECK(r.worst_error <= 1e-6);
  }
}

TEST_CASE("stability: a pinched and an inverted solid are repaired or refused, never broken output", "[stability]") {
  const std::vector<FractureHazard> all = fracture_hazards(true);
  for (const char* name : {"inverted-orientation", "duplicated-vertices", "pinched-vertex"}) {
    const HazardResult r = run_fracture_hazard(find_fracture_hazard(all, name), "plane-slice", test::builtin_registries());
    INFO(name << ": " << outcome_tag(r.outcome) << " " << r.detail);
    CHECK((r.outcome == HazardOutcome::valid || r.outcome == HazardOutcome::rejected_input));
  }
}

TEST_CASE("stability: stress hazards give finite figures and report the solver", "[stability]") {
  for (const StressHazard& h : stress_hazards(true)) {
    if (h.graph.node_count() > 100) continue;  // the long chain runs in the CLI test below
    const HazardResult r = run_stress_hazard(h, "von-mises", test::builtin_registries());
    INFO(h.name << ": " << outcome_tag(r.outcome) << " " << r.detail);
    CHECK((r.outcome == HazardOutcome::valid || r.outcome == HazardOutcome::rejected_input));
    CHECK(std::isfinite(r.residual));
  }
}

TEST_CASE("stability: the CLI runs a quick battery, prints a table and writes JSON", "[stability][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / ("shatter_stability_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto json = dir / "stability.json";
  const auto run = run_cli("stability --quick --algo plane-slice --model connection-count --hazard cut-through-vertices "
                           "--hazard thin-plate --hazard chain-1000 --hazard no-anchor --json " + json.string());
  INFO(run.out << run.err);
  CHECK(run.exit_code == 0);
  CHECK(run.out.find("| hazard | algorithm | outcome |") != std::string::npos);
  REQUIRE(std::filesystem::exists(json));
  const nlohmann::json doc = nlohmann::json::parse(shatter::test::slurp(json));
  CHECK(doc.at("results").size() == 4);
  for (const auto& r : doc.at("results")) CHECK(r.at("outcome") == "VALID");
  std::filesystem::remove_all(dir);
}

TEST_CASE("stability: bad flags exit 2 with one line and write nothing", "[stability][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / ("shatter_stability_bad_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto json = dir / "out.json";
  for (const std::string args : {"--algo nosuch", "--model nosuch", "--hazard nosuch", "--timeout -1", "--bogus",
                                 "--json /nonexistent_folder/x.json"}) {
    const auto run = run_cli("stability --quick " + args + (args.find("--json") == 0 ? "" : " --json " + json.string()));
    INFO(args << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(shatter::test::line_count(run.err) == 1);
    CHECK_FALSE(std::filesystem::exists(json));
  }
  std::filesystem::remove_all(dir);
}
