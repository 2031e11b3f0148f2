// A grid cell run in a forked child (`grid --timeout`): its results come back unchanged, a cell past
// the limit or one that crashes becomes a failed cell, an error stays an error; and a failed cell in
// every output (results JSON and its reader, CSV, Markdown, compare, Google Benchmark JSON).

#include "harness/compare/grid_compare.h"
#include "harness/grid/isolated_cell.h"
#include "harness/results/gbench_reporter.h"
#include "harness/results/grid_merge.h"
#include "harness/results/grid_reader.h"
#include "harness/results/cell_summary.h"
#include "harness/results/grid_csv_reporter.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_markdown_reporter.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace {

using namespace shatter;

/// The settings of cell 100 x 25.
GridCell settings() {
  GridCell c;
  c.prefracture = 100;
  c.runtime = 25;
  c.prefracturer = c.fracturer = "plane-slice";
  c.stress = "von-mises";
  return c;
}

/// A cell as a run would leave it: two repetitions with figures that are not short decimals.
GridCell ran_cell() {
  GridCell c = settings();
  for (int k = 0; k < 2; ++k) {
    GridSample s;
    s.seed = static_cast<std::uint64_t>(k + 1);
    s.frame_ms = {0.1 + k / 3.0, 2.0 / 3.0, 1e-7 * (k + 1)};
    s.worst_frame_ms = s.frame_ms[0];
    s.event_ms = 2.0 / 3.0;
    s.event_frame = 1;
    s.stages_ms[static_cast<std::size_t>(Stage::physics)] = 0.1 + 0.2;
    s.figures.set("fragments", 101);
    s.figures.set("latency_ms", 50.0 / 3.0);
    c.samples.push_back(s);
  }
  c.worst_frame_ms = 0.1 + 1.0 / 6.0;
  c.frame_ms.median = 2.0 / 3.0;
  c.accuracy.prefracture_volume_error = 1.0 / 3.0 * 1e-12;
  c.stages_run = {"prefracture", "physics"};
  c.stages_skipped = {{"stress", "no anchors"}};
  summarise_cell_figures(c, 50.0);
  return c;
}

RunContext context() {
  RunContext c;
  c.commit = "0123456789ab";
  c.cores = 2;
  c.fingerprint = context_fingerprint(c);
  return c;
}

/// A two-cell grid whose second cell failed with `reason`.
GridResult grid_with_failed_cell(const std::string& reason) {
  GridResult g;
  g.budget_ms = 33.3;
  g.repetitions = 2;
  g.frames = 3;
  g.cell_timeout_s = 0.5;
  GridCell ok = ran_cell();
  ok.prefracture = 10;
  g.cells.push_back(ok);
  GridCell failed = settings();
  failed.failed = reason;
  failed.within_budget = failed.within_latency_budget = false;
  g.cells.push_back(failed);
  return g;
}

}  // namespace

TEST_CASE("isolated cell: a cell run in a child comes back bit for bit", "[grid][timeout]") {
  const GridCell cell = ran_cell();
  const Result<GridCell> back = run_cell_isolated([&] { return Result<GridCell>(cell); }, settings(), 30.0, 50.0);
  REQUIRE(back.ok());
  CHECK(back->failed.empty());
  CHECK(grid_cell_to_json(*back) == grid_cell_to_json(cell));
  REQUIRE(back->samples.size() == 2);
  CHECK(back->samples[0].frame_ms == cell.samples[0].frame_ms);
  CHECK(back->worst_frame_ms == cell.worst_frame_ms);
}

TEST_CASE("isolated cell: past the limit the cell fails with the reason, and the child is gone", "[grid][timeout]") {
  const auto start = std::chrono::steady_clock::now();
  const Result<GridCell> late = run_cell_isolated(
      [] {
        std::this_thread::sleep_for(std::chrono::seconds(30));
        return Result<GridCell>(ran_cell());
      },
      settings(), 0.3, 50.0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(late.ok());
  CHECK(late->failed == "timeout after 0.3 s");
  CHECK(late->prefracture == 100);
  CHECK(late->runtime == 25);
  CHECK(late->samples.empty());
  CHECK_FALSE(late->within_budget);
  CHECK(seconds < 10.0);
}

TEST_CASE("isolated cell: a crash fails the cell, and an error of the run stays an error", "[grid][timeout]") {
  const Result<GridCell> crash = run_cell_isolated(
      []() -> Result<GridCell> {
        std::raise(SIGSEGV);
        return ran_cell();
      },
      settings(), 30.0, 50.0);
  REQUIRE(crash.ok());
  CHECK_THAT(crash->failed, Catch::StartsWith("crashed: signal 11"));

  const Result<GridCell> refused =
      run_cell_isolated([] { return Result<GridCell>(Error{"cell 100 x 25: voronoi: no"}); }, settings(), 30.0, 50.0);
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().message == "cell 100 x 25: voronoi: no");
}

TEST_CASE("grid results: a failed cell in the JSON, its reader, the CSV and the Markdown", "[grid][timeout]") {
  const GridResult g = grid_with_failed_cell("timeout after 0.5 s");
  CHECK_FALSE(g.passed());
  const nlohmann::ordered_json j = grid_to_json(g, {{"name", "synthetic"}}, context());
  CHECK(j.at("cell_timeout_s") == 0.5);
  CHECK(j.at("passed") == false);
  const auto& failed = j.at("cells")[1];
  CHECK(failed.at("failed") == "timeout after 0.5 s");
  CHECK(failed.at("within_budget") == false);
  CHECK(failed.at("samples").empty());
  CHECK_FALSE(failed.contains("worst_frame_ms"));
  CHECK_FALSE(j.at("cells")[0].contains("failed"));

  const Result<StoredGrid> read = grid_results_from_json(j, "g.json");
  REQUIRE(read.ok());
  REQUIRE(read->grid.cells.size() == 2);
  CHECK(read->grid.cells[0].failed.empty());
  CHECK(read->grid.cells[1].failed == "timeout after 0.5 s");
  CHECK(read->grid.cell_timeout_s == 0.5);
  CHECK_FALSE(read->grid.passed());

  // Every CSV line has the header's number of fields; the failed cell's last one is its reason.
  const std::string csv = grid_to_csv(g);
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < csv.size();) {
    const std::size_t end = csv.find('\n', at);
    lines.push_back(csv.substr(at, end - at));
    at = end + 1;
  }
  REQUIRE(lines.size() == 3);
  const auto fields = [](const std::string& line) { return std::count(line.begin(), line.end(), ',') + 1; };
  CHECK(fields(lines[1]) == fields(lines[0]));
  CHECK(fields(lines[2]) == fields(lines[0]));
  CHECK_THAT(lines[0], Catch::EndsWith(",failed"));
  CHECK_THAT(lines[1], Catch::EndsWith(","));
  CHECK_THAT(lines[2], Catch::StartsWith("100,25,") && Catch::EndsWith(",timeout after 0.5 s"));

  const std::string md = grid_to_markdown(g, "synthetic");
  CHECK_THAT(md, Catch::Contains("**timeout after 0.5 s !**"));
  CHECK_THAT(md, Catch::Contains("1 of 2 cells failed (marked !): cell 100 x 25: timeout after 0.5 s."));
  CHECK_THAT(md, !Catch::Contains("All 2 cells within"));

  // A reason with a comma or a quote is one quoted CSV field.
  CHECK_THAT(grid_to_csv(grid_with_failed_cell("crashed: \"x\", y")), Catch::EndsWith(",\"crashed: \"\"x\"\", y\"\n"));
}

TEST_CASE("grid results: compare refuses a failed cell, and gbench marks it as an error", "[grid][timeout]") {
  const GridResult g = grid_with_failed_cell("crashed: signal 11 (Segmentation fault)");
  Result<StoredGrid> a = grid_results_from_json(grid_to_json(g, {{"name", "synthetic"}}, context()), "a.json");
  REQUIRE(a.ok());
  a->path = "a.json";
  const CompareReport r = compare_grids(*a, *a, {});
  CHECK(r.failed());
  bool named = false;
  for (const std::string& m : r.mismatches)
    named = named || m == "cell 100 x 25 failed in a.json: crashed: signal 11 (Segmentation fault)";
  CHECK(named);

  const nlohmann::ordered_json gb = grid_to_gbench_json(g, "synthetic", context());
  int errors = 0;
  for (const auto& b : gb.at("benchmarks"))
    if (b.contains("error_occurred")) {
      ++errors;
      CHECK(b.at("name") == "synthetic/100x25/worst_frame");
      CHECK(b.at("error_message") == "crashed: signal 11 (Segmentation fault)");
    }
  CHECK(errors == 1);
}

TEST_CASE("grid results: shards with failed cells merge, shards of different time limits do not", "[grid][timeout]") {
  const GridResult whole = grid_with_failed_cell("timeout after 0.5 s");
  GridResult s0 = whole, s1 = whole;
  s0.cells = {whole.cells[0]};
  s1.cells = {whole.cells[1]};
  s0.shard_index = 0;
  s1.shard_index = 1;
  s0.shard_count = s1.shard_count = 2;
  const auto stored = [](const GridResult& g, const std::string& name) {
    Result<StoredGrid> s = grid_results_from_json(grid_to_json(g, {{"name", "synthetic"}}, context()), name);
    REQUIRE(s.ok());
    s->path = name;
    return *s;
  };
  const Result<StoredGrid> merged = merge_grids({stored(s0, "s0.json"), stored(s1, "s1.json")});
  REQUIRE(merged.ok());
  REQUIRE(merged->grid.cells.size() == 2);
  CHECK(merged->grid.cells[1].failed == "timeout after 0.5 s");
  CHECK(merged->grid.cell_timeout_s == 0.5);
  CHECK_FALSE(merged->grid.passed());
  s1.cell_timeout_s = 2.0;
  const Result<StoredGrid> mixed = merge_grids({stored(s0, "s0.json"), stored(s1, "s1.json")});
  REQUIRE_FALSE(mixed.ok());
  CHECK(mixed.error().message == "merge: s1.json differs from s0.json in cell_timeout_s");
}

TEST_CASE("cli: report shows a failed cell in the heat map and the table, and refuses it as --cell",
          "[cli][report][timeout]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "shatter_isolated_cell_tests" / "report";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path grid = dir / "grid.json";
  std::ofstream(grid) << grid_to_json(grid_with_failed_cell("timeout after 0.5 s"), {{"name", "synthetic"}}, context())
                             .dump(1);
  const auto ok = shatter::test::run_cli("report " + grid.string() + " --out " + (dir / "report").string());
  INFO(ok.err);
  REQUIRE(ok.exit_code == 0);
  const std::string page = shatter::test::slurp(dir / "report" / "report.md");
  CHECK_THAT(page, Catch::Contains("0 of 2 cells over it, 1 failed (`grid --timeout`)"));
  CHECK_THAT(page, Catch::Contains("| **timeout after 0.5 s !** |"));
  CHECK_THAT(page, Catch::Contains("### Stages of cell 10 x 25"));  // the largest cell that ran
  CHECK_THAT(shatter::test::slurp(dir / "report" / "grid-synthetic.dat"), Catch::Contains("NaN \"failed\" 2"));

  const auto refused =
      shatter::test::run_cli("report " + grid.string() + " --cell 100,25 --out " + (dir / "other").string());
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.err, Catch::Contains("--cell: cell 100 x 25") && Catch::Contains("failed (timeout after 0.5 s)"));
  CHECK_FALSE(fs::exists(dir / "other"));
  fs::remove_all(dir);
}
