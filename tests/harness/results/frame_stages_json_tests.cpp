// Per-frame stage times in the results JSON: written per stage that took time, one value per frame,
// on one line each; the worst frame's breakdown is that frame's column (per sample) and the median
// repetition's (per cell); they read back and merge as written; a file without them still reads.

#include "harness/results/cell_summary.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_merge.h"
#include "harness/results/grid_reader.h"
#include "harness/results/results_json_text.h"
#include "harness/results/worst_frame.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace shatter;
using Json = nlohmann::ordered_json;

constexpr std::size_t kPhysics = static_cast<std::size_t>(Stage::physics);
constexpr std::size_t kFracture = static_cast<std::size_t>(Stage::runtime_fracture);

RunContext context() {
  RunContext c;
  c.commit = "0123456789ab";
  c.cores = 2;
  c.fingerprint = context_fingerprint(c);
  return c;
}

/// A sample of four frames whose slowest is `worst` (at frame 2), physics every frame and the runtime
/// fracture in the slowest one; stage totals are the sums of the frames.
GridSample sample(double worst, std::uint64_t seed) {
  GridSample s;
  s.seed = seed;
  s.frame_ms = {1.5, 1.25, worst, 1.0};
  s.worst_frame_ms = worst;
  FrameStageTimes t;
  t[kPhysics] = {1.0, 1.0, 1.0 / 3.0, 0.75};
  t[kFracture] = {0.0, 0.0, worst - 2.0, 0.0};
  s.frame_stages_ms = t;
  s.stages_ms = sum_over_frames(t);
  s.event_frame = 2;
  s.event_ms = worst;
  return s;
}

/// One cell of three repetitions whose worst frames are 9, 5 and 7 ms: the median is repetition 2.
GridResult grid() {
  GridResult g;
  g.budget_ms = 33.3;
  g.repetitions = 3;
  g.frames = 4;
  GridCell c;
  c.prefracture = 10;
  c.runtime = 5;
  c.prefracturer = c.fracturer = "plane-slice";
  c.stress = "von-mises";
  c.samples = {sample(9.0, 1), sample(5.0, 2), sample(7.0, 3)};
  summarise_cell(c, g.budget_ms, g.latency_budget_ms);
  g.cells.push_back(c);
  return g;
}

Json written() { return grid_to_json(grid(), {{"name", "synthetic"}}, context()); }

}  // namespace

TEST_CASE("frame stages: written per stage that ran, and the worst frame is that frame's column", "[results]") {
  const Json j = written();
  const Json& cell = j["cells"][0];
  const Json& s = cell["samples"][0];
  REQUIRE(s["frame_stages_ms"].size() == 2);  // physics and runtime_fracture only
  CHECK(s["frame_stages_ms"]["physics"].size() == s["frame_ms"].size());
  CHECK(s["frame_stages_ms"]["runtime_fracture"][0].is_number_integer());  // a zero is written 0
  const Json& worst = s["worst_frame_stages_ms"];
  REQUIRE(worst.size() == 2);
  for (auto it = worst.begin(); it != worst.end(); ++it)
    CHECK(it.value() == s["frame_stages_ms"][it.key()][2]);
  // The cell: the repetition whose worst frame is the median one (7 ms: repetition 2).
  CHECK(cell["worst_frame_repetition"] == 2);
  CHECK(cell["worst_frame_ms"] == 7.0);
  CHECK(cell["worst_frame_stages_ms"] == cell["samples"][2]["worst_frame_stages_ms"]);
}

TEST_CASE("frame stages: the median repetition of an even count is the lower middle one", "[results]") {
  GridCell c = grid().cells[0];
  c.samples.push_back(sample(8.0, 4));  // worst frames 9, 5, 7, 8: lower middle 7
  const std::optional<WorstFrame> w = cell_worst_frame(c);
  REQUIRE(w);
  CHECK(w->repetition == 2);
  CHECK(w->frame == 2);
  CHECK(w->stages[kFracture] == 5.0);
  const auto top = largest_stages(w->stages, 1);
  REQUIRE(top.size() == 1);
  CHECK(top[0].first == Stage::runtime_fracture);
}

TEST_CASE("frame stages: the results text puts them on one line and is dump(1) elsewhere", "[results]") {
  const Json j = written();
  const std::string text = results_json_text(j);
  CHECK(Json::parse(text) == j);
  CHECK(text.find("\"physics\": [1.0, 1.0, 0.3333333333333333, 0.75]") != std::string::npos);
  Json without = j;
  for (Json& s : without["cells"][0]["samples"]) s.erase("frame_stages_ms");
  CHECK(results_json_text(without) == without.dump(1));
}

TEST_CASE("frame stages: they read back, write the same bytes and survive a merge", "[results]") {
  const Json j = written();
  const Result<StoredGrid> back = grid_results_from_json(j, "r.json");
  REQUIRE(back);
  const GridResult g = grid();
  const GridSample& a = g.cells[0].samples[0];
  const GridSample& b = back->grid.cells[0].samples[0];
  REQUIRE(b.frame_stages_ms);
  CHECK(*b.frame_stages_ms == *a.frame_stages_ms);
  CHECK(results_json_text(grid_to_json(back->grid, back->case_block, back->context)) == results_json_text(j));

  StoredGrid first = *back, second = *back;
  first.path = "a.json";
  second.path = "b.json";
  second.context.date = "another run";
  second.grid.cells[0].samples[0].frame_ms[0] += 1.0;  // not the same run
  const Result<StoredGrid> merged = merge_grids({first, second}, MergeParts::repetitions);
  REQUIRE(merged);
  REQUIRE(merged->grid.cells[0].samples.size() == 6);
  for (const GridSample& s : merged->grid.cells[0].samples) CHECK(s.frame_stages_ms);
  CHECK(grid_cell_to_json(merged->grid.cells[0]).contains("worst_frame_stages_ms"));
}

TEST_CASE("frame stages: a file without them reads, and a bad array is an error naming it", "[results]") {
  Json old = written();
  old["cells"][0].erase("worst_frame_stages_ms");
  old["cells"][0].erase("worst_frame_repetition");
  for (Json& s : old["cells"][0]["samples"]) {
    s.erase("frame_stages_ms");
    s.erase("worst_frame_stages_ms");
  }
  const Result<StoredGrid> back = grid_results_from_json(old, "old.json");
  REQUIRE(back);
  CHECK_FALSE(back->grid.cells[0].samples[0].frame_stages_ms);
  CHECK_FALSE(cell_worst_frame(back->grid.cells[0]));
  CHECK(grid_to_json(back->grid, back->case_block, back->context) == old);

  const auto error_of = [](const Json& j) {
    const Result<StoredGrid> r = grid_results_from_json(j, "r.json");
    REQUIRE_FALSE(r);
    return r.error().message;
  };
  Json j = written();
  j["cells"][0]["samples"][0]["frame_stages_ms"]["physics"] = {1.0, 2.0};
  CHECK(error_of(j) == "r.json: cells[0].samples[0].frame_stages_ms.physics: expected 4 values (one per frame), got 2");
  j = written();
  j["cells"][0]["samples"][1]["frame_stages_ms"]["lunch"] = {1.0, 2.0, 3.0, 4.0};
  CHECK(error_of(j) == "r.json: cells[0].samples[1].frame_stages_ms.lunch: not a stage name");
  j = written();
  j["cells"][0]["samples"][0]["frame_stages_ms"]["physics"][1] = -1.0;
  CHECK(error_of(j) == "r.json: cells[0].samples[0].frame_stages_ms.physics: expected times >= 0");
}
