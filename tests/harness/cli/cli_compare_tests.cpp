// `shatterbench compare`, `merge`, and the grid's gate outputs (shards, gbench format, JUnit,
// baselines) from the command line.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using shatter::test::line_count;
using shatter::test::run_cli;
using shatter::test::slurp;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_compare_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

const std::string kSmall = "grid --case building --prefracture 10,20 --runtime 5,10 --repetitions 1 --frames 2 --no-cache";

}  // namespace

TEST_CASE("cli: merge of two shards holds the cells of the unsharded run", "[cli][compare]") {
  const auto dir = scratch("shards");
  REQUIRE(run_cli(kSmall + " --json " + (dir / "all.json").string()).exit_code == 0);
  REQUIRE(run_cli(kSmall + " --shard 0/2 --json " + (dir / "s0.json").string()).exit_code == 0);
  REQUIRE(run_cli(kSmall + " --shard 1/2 --json " + (dir / "s1.json").string()).exit_code == 0);
  const auto s0 = nlohmann::json::parse(slurp(dir / "s0.json"));
  CHECK(s0.at("cells").size() == 2);
  CHECK(s0.at("shard").at("count") == 2);
  const auto r = run_cli("merge " + (dir / "s1.json").string() + " " + (dir / "s0.json").string() + " --out " +
                         (dir / "merged.json").string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto merged = nlohmann::json::parse(slurp(dir / "merged.json"));
  const auto all = nlohmann::json::parse(slurp(dir / "all.json"));
  REQUIRE(merged.at("cells").size() == all.at("cells").size());
  CHECK_FALSE(merged.contains("shard"));
  for (std::size_t i = 0; i < all.at("cells").size(); ++i) {
    const auto& a = all.at("cells")[i];
    const auto& m = merged.at("cells")[i];
    CHECK(a.at("prefracture") == m.at("prefracture"));
    CHECK(a.at("runtime") == m.at("runtime"));
    // The deterministic parts of every repetition agree (the times are other runs' times).
    for (const char* key : {"seed", "fragments", "hit", "pieces", "broken_bonds", "falling_clusters", "bodies"})
      CHECK(a.at("samples")[0].at(key) == m.at("samples")[0].at(key));
  }
  // A shard twice is refused, naming the file.
  const auto twice = run_cli("merge " + (dir / "s0.json").string() + " " + (dir / "s0.json").string() + " --out " +
                             (dir / "bad.json").string());
  CHECK(twice.exit_code == 2);
  CHECK(twice.err.find("are the same file") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "bad.json"));
}

TEST_CASE("cli: merge --repetitions joins runs of the same cells", "[cli][compare]") {
  const auto dir = scratch("repetitions");
  const std::string run = kSmall + " --same-seed --json ";
  REQUIRE(run_cli(run + (dir / "r1.json").string()).exit_code == 0);
  REQUIRE(run_cli(run + (dir / "r2.json").string()).exit_code == 0);
  const auto r = run_cli("merge --repetitions " + (dir / "r1.json").string() + " " + (dir / "r2.json").string() +
                         " --out " + (dir / "joined.json").string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto joined = nlohmann::json::parse(slurp(dir / "joined.json"));
  CHECK(joined.at("repetitions") == 2);
  REQUIRE(joined.at("cells").size() == 4);
  for (const auto& c : joined.at("cells")) CHECK(c.at("samples").size() == 2);
  // Shards are not repetitions: without the flag the same cells twice are refused.
  const auto as_shards = run_cli("merge " + (dir / "r1.json").string() + " " + (dir / "r2.json").string() + " --out " +
                                 (dir / "bad.json").string());
  CHECK(as_shards.exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "bad.json"));
}

TEST_CASE("cli: compare passes on itself, fails on a missing cell, refuses bad input", "[cli][compare]") {
  const auto dir = scratch("compare");
  const auto all = (dir / "all.json").string(), part = (dir / "part.json").string();
  REQUIRE(run_cli(kSmall + " --json " + all).exit_code == 0);
  REQUIRE(run_cli(kSmall + " --shard 0/2 --json " + part).exit_code == 0);
  const auto same = run_cli("compare " + all + " " + all + " --junit " + (dir / "c.xml").string());
  INFO(same.err);
  CHECK(same.exit_code == 0);
  CHECK(same.out.find("**PASS**") != std::string::npos);
  CHECK(same.err.find("repetitions") != std::string::npos);  // the warning: 1 repetition cannot show anything
  CHECK(slurp(dir / "c.xml").find("<testsuites") != std::string::npos);
  const auto missing = run_cli("compare " + all + " " + part);
  CHECK(missing.exit_code == 1);
  CHECK(missing.err.find("missing") != std::string::npos);
  CHECK(run_cli("compare " + all + " " + (dir / "nope.json").string()).exit_code == 2);
  CHECK(run_cli("compare " + all + " " + all + " --max-slowdown -1").exit_code == 2);
  CHECK(run_cli("compare " + all + " " + all + " --alpha 2").exit_code == 2);
  CHECK(run_cli("compare " + all + " " + all + " --metric cycles").exit_code == 2);
  CHECK(run_cli("compare " + all + " " + all + " --metric instructions").exit_code == 1);  // no counts in them
  std::ofstream(dir / "broken.json") << "{\"schema_version\": 1, \"cells\": [";
  const auto broken = run_cli("compare " + all + " " + (dir / "broken.json").string());
  CHECK(broken.exit_code == 2);
  CHECK(line_count(broken.err) == 1);
  CHECK(broken.err.find("broken.json") != std::string::npos);
}

TEST_CASE("cli: grid writes gbench JSON and JUnit, and shards refuse bad specs", "[cli][compare]") {
  const auto dir = scratch("formats");
  const auto r = run_cli("grid --case building --prefracture 10 --runtime 5 --repetitions 2 --frames 2 --no-cache "
                         "--budget-ms 0.001 --format gbench --json " + (dir / "g.json").string() + " --junit " +
                         (dir / "g.xml").string());
  CHECK(r.exit_code == 1);
  const auto g = nlohmann::json::parse(slurp(dir / "g.json"));
  CHECK(g.at("benchmarks")[0].at("name") == "building/10x5/worst_frame");
  CHECK(g.at("benchmarks")[0].at("time_unit") == "ns");
  const std::string xml = slurp(dir / "g.xml");
  CHECK(xml.find("failures=\"1\"") != std::string::npos);
  CHECK(xml.find("<failure message=\"worst frame") != std::string::npos);
  for (const char* shard : {"2/2", "x", "1/0", "-1/3"}) {
    const auto bad = run_cli(kSmall + " --shard " + shard);
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("--shard") != std::string::npos);
  }
  CHECK(run_cli(kSmall + " --format xml").exit_code == 2);
  CHECK(run_cli(kSmall + " --metric cycles").exit_code == 2);
}

TEST_CASE("cli: --gbench writes Google Benchmark's JSON beside the native results", "[cli][compare]") {
  const auto dir = scratch("gbench-beside");
  const auto r = run_cli("grid --case building --prefracture 10 --runtime 5 --repetitions 2 --frames 2 --no-cache "
                         "--json " + (dir / "n.json").string() + " --gbench " + (dir / "g.json").string());
  CHECK(r.exit_code == 0);
  const auto native = nlohmann::json::parse(slurp(dir / "n.json"));
  CHECK(native.contains("cells"));
  const auto g = nlohmann::json::parse(slurp(dir / "g.json"));
  CHECK(g.at("benchmarks")[0].at("name") == "building/10x5/worst_frame");
  CHECK(g.at("benchmarks")[0].at("run_type") == "iteration");
  const auto a = run_cli("grid --case building --prefracture 10 --runtime 5 --repetitions 2 --frames 2 --no-cache "
                         "--gbench " + (dir / "a.json").string() + " --gbench-aggregates-only");
  CHECK(a.exit_code == 0);
  const auto aggregates = nlohmann::json::parse(slurp(dir / "a.json"));  // kept: the loop reads into it
  for (const auto& b : aggregates.at("benchmarks")) CHECK(b.at("run_type") == "aggregate");
  // One file cannot be both outputs.
  CHECK(run_cli(kSmall + " --json " + (dir / "same.json").string() + " --gbench " + (dir / "same.json").string())
            .exit_code == 2);
}

TEST_CASE("cli: a baseline changes only with --update-baseline, and not when the gate fails", "[cli][compare]") {
  const auto dir = scratch("baselines");
  const auto folder = dir / "baselines";
  const std::string base = " --baseline-dir " + folder.string();
  // Writing into the baseline folder without the flag is refused.
  const auto refused = run_cli(kSmall + base + " --json " + (folder / "building.json").string());
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("--update-baseline") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(folder / "building.json"));
  // The explicit update writes BASELINE-DIR/<case>.json.
  const auto updated = run_cli(kSmall + base + " --update-baseline");
  INFO(updated.err);
  REQUIRE(updated.exit_code == 0);
  const std::string first = slurp(folder / "building.json");
  CHECK(nlohmann::json::parse(first).at("cells").size() == 4);
  // A failing gate leaves the baseline as it was.
  const auto failed = run_cli(kSmall + base + " --update-baseline --budget-ms 0.001");
  CHECK(failed.exit_code == 1);
  CHECK(failed.err.find("not updated") != std::string::npos);
  CHECK(slurp(folder / "building.json") == first);
}
