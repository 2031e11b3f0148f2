// One record for results: a figure added in one place (the record of each run, through
// GridOptions::extra_figures) reaches every output format and reads back from the results JSON.

#include "tests/support/builtin_registries.h"
#include "harness/cases/case_library.h"
#include "harness/grid/grid_runner.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_reader.h"
#include "harness/results/grid_reporter.h"
#include "harness/results/results_json_text.h"

#include <catch2/catch.hpp>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace shatter;

/// A figure of the test's own: the pre-fracture's fragment count times 1.5, in "units".
const FigureSpec kExtra{"extra_units", FigureKind::number, "units", CellSummary::max,
                        kFigureLast, kFigureLast, kFigureEverywhere, true, 0.0};

double extra_value(const RunResult& run) { return 1.5 * static_cast<double>(run.fragments.size()); }

std::string render(std::string_view format, const GridReport& report) {
  const std::unique_ptr<GridReporter> reporter = make_grid_reporter(format);
  REQUIRE(reporter);
  CHECK(reporter->format() == format);
  return reporter->render(report);
}

}  // namespace

TEST_CASE("one record: a figure added to each run's record reaches every output", "[grid][results]") {
  Result<Case> c = find_case("building");
  REQUIRE(c);
  Result<PreparedCase> p = prepare_case(std::move(*c));
  REQUIRE(p);
  GridOptions o;
  o.prefracture = {6};
  o.runtime = {3};
  o.repetitions = 2;
  o.frames = 3;
  o.partition_samples = 0;
  o.extra_figures = [](const RunResult& run, FigureRecord& record) { record.add(kExtra, extra_value(run)); };
  const Result<GridResult> grid = run_grid(*p, o, test::builtin_registries());
  REQUIRE(grid);
  const GridCell& cell = grid->cells.at(0);
  REQUIRE(cell.samples.size() == 2);
  const double first = cell.samples[0].figures.value("extra_units");
  const double second = cell.samples[1].figures.value("extra_units");
  CHECK(first >= 9.0);
  const double summary = std::max(first, second);
  REQUIRE(cell.summaries.find("extra_units") != nullptr);
  CHECK(cell.summaries.value("extra_units") == summary);

  RunContext context;
  context.commit = "0123456789ab";
  context.fingerprint = context_fingerprint(context);
  const GridReport report{*grid, p->spec.name, case_to_json(p->spec), context};
  const std::string text = fmt::format("{:g}", summary);

  // Results JSON: per sample and the cell's summary.
  const std::string json_text = render("json", report);
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(json_text);
  CHECK(json["cells"][0]["samples"][0]["extra_units"].get<double>() == first);
  CHECK(json["cells"][0]["samples"][1]["extra_units"].get<double>() == second);
  CHECK(json["cells"][0]["extra_units"].get<double>() == summary);

  // CSV: a column before `failed`.
  const std::string csv = render("csv", report);
  CHECK_THAT(csv, Catch::Contains(",extra_units,failed\n"));
  CHECK_THAT(csv, Catch::Contains("," + text + ",\n"));

  // Google Benchmark JSON: a counter of the cell's worst_frame entries, per repetition and in the
  // mean and median aggregates (stddev and cv are of the counter's spread).
  const nlohmann::json gbench = nlohmann::json::parse(render("gbench", report));
  int counted = 0;
  for (const auto& b : gbench["benchmarks"]) {
    if (b["run_name"].get<std::string>().find("/worst_frame") == std::string::npos) {
      CHECK_FALSE(b.contains("extra_units"));
      continue;
    }
    REQUIRE(b.contains("extra_units"));
    const double v = b["extra_units"].get<double>();
    const std::string aggregate = b.contains("aggregate_name") ? b["aggregate_name"].get<std::string>() : "";
    if (aggregate == "stddev" || aggregate == "cv") continue;
    CHECK((v == first || v == second || v == 0.5 * (first + second)));
    ++counted;
  }
  CHECK(counted == 4);  // two repetitions, the mean and the median

  // JUnit: a property of the suite named after the cell's test case.
  CHECK_THAT(render("junit", report), Catch::Contains("<property name=\"cell 6 x 3: extra_units\" value=\"" + text + "\"/>"));

  // Markdown: a table of its own.
  const std::string md = render("markdown", report);
  CHECK_THAT(md, Catch::Contains("`extra_units`, units (largest over repetitions)"));
  CHECK_THAT(md, Catch::Contains("| 6 | " + text + " |"));

  // Read back from the JSON, a figure this build does not list: the same values, and written again
  // the same bytes.
  const Result<StoredGrid> back = grid_results_from_json(json, "extra.json");
  REQUIRE(back);
  const GridCell& read = back->grid.cells.at(0);
  CHECK(read.samples[0].figures.value("extra_units") == first);
  CHECK(read.samples[1].figures.value("extra_units") == second);
  CHECK(read.summaries.value("extra_units") == summary);
  CHECK(results_json_text(grid_to_json(back->grid, back->case_block, back->context)) + "\n" == json_text);
}
