// The grid runner in process, on a one-cell grid of a built-in case: the cell's summaries are what
// its samples say (medians, the largest step, the union of stages), and the budget is judged.

#include "tests/support/builtin_registries.h"
#include "harness/cases/case_library.h"
#include "harness/grid/grid_runner.h"
#include "harness/results/sample_statistics.h"

#include "tests/support/prepared_case.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using namespace shatter;

using test::prepared;

/// One cell (6 x 3), 3 repetitions of 4 frames, no cache.
GridOptions one_cell() {
  GridOptions o;
  o.prefracture = {6};
  o.runtime = {3};
  o.repetitions = 3;
  o.frames = 4;
  o.partition_samples = 16;
  return o;
}

std::vector<double> per_sample(const GridCell& c, double GridSample::*field) {
  std::vector<double> v;
  for (const GridSample& s : c.samples) v.push_back(s.*field);
  return v;
}

std::vector<double> per_sample(const GridCell& c, const std::string& figure) {
  std::vector<double> v;
  for (const GridSample& s : c.samples) v.push_back(s.figures.value(figure));
  return v;
}

}  // namespace

TEST_CASE("grid runner: a one-cell grid summarises its samples", "[grid]") {
  const PreparedCase p = prepared("building");
  const Result<GridResult> grid = run_grid(p, one_cell(), test::builtin_registries());
  REQUIRE(grid);
  REQUIRE(grid->cells.size() == 1);
  const GridCell& c = grid->cells.front();
  CHECK(c.failed.empty());
  CHECK(c.prefracture == 6);
  CHECK(c.runtime == 3);
  CHECK(c.prefracturer == p.spec.prefracture.fracturer);
  CHECK(c.fracturer == p.spec.runtime.fracturer);
  CHECK(c.stress == p.spec.stress.model);
  CHECK(grid->frames == 4);
  CHECK(grid->budget_ms == p.spec.budget_ms);
  REQUIRE(c.samples.size() == 3);
  for (const GridSample& s : c.samples) CHECK(s.frame_ms.size() == 4);
  CHECK(c.samples[0].seed + 1 == c.samples[1].seed);

  // Timings: medians over repetitions, the pooled frames.
  CHECK(c.worst_frame_ms == median_of(per_sample(c, &GridSample::worst_frame_ms)));
  CHECK(c.event_ms == median_of(per_sample(c, &GridSample::event_ms)));
  for (std::size_t k = 0; k < kStageCount; ++k) {
    std::vector<double> v;
    for (const GridSample& s : c.samples) v.push_back(s.stages_ms[k]);
    CHECK(c.stages_ms[k] == median_of(v));
  }
  std::vector<double> frames;
  for (const GridSample& s : c.samples) frames.insert(frames.end(), s.frame_ms.begin(), s.frame_ms.end());
  CHECK(c.frame_ms.count == 12);
  CHECK(c.frame_ms.max == *std::max_element(frames.begin(), frames.end()));

  // Figures: each by its spec's summary.
  CHECK(c.summaries.value("bodies") == median_of(per_sample(c, "bodies")));
  CHECK(c.summaries.value("latency_ms") == median_of(per_sample(c, "latency_ms")));
  const std::vector<double> steps = per_sample(c, "largest_step_ms");
  CHECK(c.summaries.value("largest_step_ms") == *std::max_element(steps.begin(), steps.end()));
  CHECK(c.samples[0].figures.value("fragments") >= 6);
  CHECK(c.summaries.find("fragments") == nullptr);  // per repetition only

  // Stages: the union over repetitions, in data-flow order, each once.
  REQUIRE_FALSE(c.stages_run.empty());
  std::vector<std::size_t> order;
  for (const std::string& name : c.stages_run) {
    const auto it = std::find_if(kAllStages.begin(), kAllStages.end(),
                                 [&](Stage s) { return stage_name(s) == name; });
    REQUIRE(it != kAllStages.end());
    order.push_back(static_cast<std::size_t>(it - kAllStages.begin()));
  }
  CHECK(std::is_sorted(order.begin(), order.end()));
  CHECK(std::adjacent_find(order.begin(), order.end()) == order.end());
  CHECK(std::find(c.stages_run.begin(), c.stages_run.end(), "prefracture") != c.stages_run.end());
}

TEST_CASE("grid runner: the budget judges the cell's worst frame", "[grid]") {
  const PreparedCase p = prepared("building");
  GridOptions o = one_cell();
  o.repetitions = 1;
  o.budget_ms = 1e-9;  // no frame is this fast
  const Result<GridResult> tight = run_grid(p, o, test::builtin_registries());
  REQUIRE(tight);
  CHECK(tight->budget_ms == 1e-9);
  CHECK_FALSE(tight->cells.front().within_budget);
  CHECK_FALSE(tight->passed());
  o.budget_ms = 1e9;
  const Result<GridResult> loose = run_grid(p, o, test::builtin_registries());
  REQUIRE(loose);
  CHECK(loose->cells.front().within_budget);
  CHECK(loose->cells.front().within_latency_budget == (loose->cells.front().summaries.value("latency_ms") <= 50.0));
}

TEST_CASE("grid runner: options resolve against the case in one place", "[grid]") {
  const PreparedCase planes = prepared("cantilever");  // explicit cuts: one pre-fracture count
  const RunSettings cuts = resolve_settings(planes.spec, {});
  CHECK(cuts.prefracture_counts == std::vector<int>{8});
  CHECK(cuts.prefracturer == "planes");
  const PreparedCase p = prepared("building");
  GridOptions o;
  const RunSettings from_case = resolve_settings(p.spec, {});
  CHECK(from_case.prefracturer == p.spec.prefracture.fracturer);
  CHECK(from_case.prefracture_counts == p.spec.grid.prefracture);
  CHECK(from_case.runtime_counts == p.spec.grid.runtime);
  CHECK(from_case.frames == p.spec.frames);
  CHECK(from_case.stress_model == p.spec.stress.model);
  const GridCell cell = grid_cell_settings(p.spec, o, 10, 5);
  CHECK(cell.fracturer == from_case.runtime_fracturer);
  o.fracturer = "plane-slice";
  o.stress_model = "tresca";
  const GridCell flagged = grid_cell_settings(p.spec, o, 10, 5);
  CHECK(flagged.prefracturer == "plane-slice");
  CHECK(flagged.fracturer == "plane-slice");
  CHECK(flagged.stress == "tresca");
}
