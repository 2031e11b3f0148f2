// The results JSON written and read back: equal, byte for byte when written again; a malformed file
// is an error naming the key; a file from before the optional figures reads with their fallbacks.

#include "harness/results/cell_summary.h"
#include "harness/results/grid_csv_reporter.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_reader.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace shatter;
using Json = nlohmann::ordered_json;

RunContext context() {
  RunContext c;
  c.commit = "0123456789ab";
  c.cores = 2;
  c.fingerprint = context_fingerprint(c);
  return c;
}

/// Two cells of two repetitions each, with figures that are not short decimals.
GridResult grid() {
  GridResult g;
  g.budget_ms = 33.3;
  g.repetitions = 2;
  g.frames = 3;
  for (const int p : {10, 20}) {
    GridCell c;
    c.prefracture = p;
    c.runtime = 5;
    c.prefracturer = c.fracturer = "plane-slice";
    c.stress = "von-mises";
    for (int k = 0; k < 2; ++k) {
      GridSample s;
      s.seed = static_cast<std::uint64_t>(k + 1);
      s.frame_ms = {0.1 + k / 3.0, 2.0 / 3.0 * p, 1e-7};
      s.worst_frame_ms = s.frame_ms[1];
      s.event_ms = s.frame_ms[1];
      s.event_frame = 1;
      s.stages_ms[static_cast<std::size_t>(Stage::stress)] = 0.1 + 0.2 * k;
      s.figures.set("fragments", p + k);
      s.figures.set("bodies", p + 2 * k);
      s.figures.set("solver.residual", 1e-13 / 3.0);
      s.figures.set("latency_ms", 50.0 / 3.0);
      c.samples.push_back(s);
    }
    c.accuracy.prefracture_volume_error = 1e-16 / 3.0;
    c.stages_run = {"prefracture", "stress"};
    c.stages_skipped = {{"debris", "the case has no debris"}};
    summarise_cell(c, g.budget_ms, g.latency_budget_ms);
    g.cells.push_back(c);
  }
  return g;
}

Json written() { return grid_to_json(grid(), {{"name", "synthetic"}}, context()); }

std::string error_of(const Json& j) {
  const Result<StoredGrid> r = grid_results_from_json(j, "r.json");
  REQUIRE_FALSE(r);
  return r.error().message;
}

}  // namespace

TEST_CASE("grid reader: what is written reads back equal, and writes the same bytes", "[results]") {
  const Json j = written();
  const Result<StoredGrid> back = grid_results_from_json(j, "r.json");
  REQUIRE(back);
  CHECK(back->case_name == "synthetic");
  REQUIRE(back->grid.cells.size() == 2);
  const GridResult g = grid();
  for (std::size_t i = 0; i < 2; ++i) {
    const GridCell& a = g.cells[i];
    const GridCell& b = back->grid.cells[i];
    CHECK(a.worst_frame_ms == b.worst_frame_ms);
    CHECK(a.accuracy.prefracture_volume_error == b.accuracy.prefracture_volume_error);
    CHECK(a.summaries.value("bodies") == b.summaries.value("bodies"));
    REQUIRE(a.samples.size() == b.samples.size());
    for (std::size_t k = 0; k < a.samples.size(); ++k) {
      CHECK(a.samples[k].frame_ms == b.samples[k].frame_ms);
      CHECK(a.samples[k].figures.value("solver.residual") == b.samples[k].figures.value("solver.residual"));
      CHECK(a.samples[k].figures.figures().size() == b.samples[k].figures.figures().size());
    }
  }
  CHECK(grid_to_json(back->grid, back->case_block, back->context).dump(1) == j.dump(1));
  CHECK(grid_to_csv(back->grid) == grid_to_csv(g));
}

TEST_CASE("grid reader: a malformed file is an error naming the key", "[results]") {
  Json j = written();
  j["cells"][0]["samples"][1].erase("bodies");
  CHECK(error_of(j) == "r.json: cells[0].samples[1].bodies: missing");
  j = written();
  j["cells"][1]["samples"][0]["fragments"] = "many";
  CHECK(error_of(j) == "r.json: cells[1].samples[0].fragments: expected an integer");
  j = written();
  j["cells"][0]["samples"][0]["solver"]["converged"] = 1;
  CHECK(error_of(j) == "r.json: cells[0].samples[0].solver.converged: expected true or false");
  j = written();
  j["cells"][0]["samples"][0].erase("solver");
  CHECK(error_of(j) == "r.json: cells[0].samples[0].solver: missing");
  j = written();
  j["cells"][0]["samples"][0]["mood"] = "fine";
  CHECK(error_of(j) == "r.json: cells[0].samples[0].mood: expected a number, true or false");
  j = written();
  j["cells"][0]["bodies"] = "a few";
  CHECK(error_of(j) == "r.json: cells[0].bodies: expected a number");
  j = written();
  j["cells"][0]["samples"][0]["frame_ms"] = {1.0, "slow"};
  CHECK(error_of(j) == "r.json: cells[0].samples[0].frame_ms: expected an array of numbers");
}

TEST_CASE("grid reader: a file from before the optional figures reads them at their fallbacks", "[results]") {
  Json j = written();
  for (Json& cell : j["cells"]) {
    for (const char* key : {"latency_ms", "latency_frames", "within_latency_budget", "largest_step_ms",
                            "bodies_peak", "particles_peak"})
      cell.erase(key);
    for (Json& s : cell["samples"])
      for (const char* key : {"latency_ms", "latency_frames", "latency_after_impact_frames", "trigger_frame",
                              "visible_frame", "event_steps", "largest_step_ms", "worst_work_ms", "bodies_peak",
                              "faded", "particles_spawned", "particles_peak"})
        s.erase(key);
  }
  const Result<StoredGrid> back = grid_results_from_json(j, "old.json");
  REQUIRE(back);
  const GridCell& c = back->grid.cells[0];
  CHECK(c.samples[0].figures.value("trigger_frame") == -1.0);
  CHECK(c.samples[0].figures.value("latency_ms") == 0.0);
  CHECK(c.summaries.value("latency_ms") == 0.0);  // recomputed from the samples
  CHECK(c.summaries.value("bodies") == 11.0);     // as written: median of 10 and 12
  CHECK(c.within_latency_budget);
}
