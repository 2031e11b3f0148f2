// compare on synthetic results with known samples; merge of shards; the Google Benchmark and JUnit
// outputs.

#include "algorithms/core/random.h"
#include "harness/compare/grid_compare.h"
#include "harness/results/gbench_reporter.h"
#include "harness/results/grid_merge.h"
#include "harness/results/cell_summary.h"
#include "harness/results/grid_csv_reporter.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_markdown_reporter.h"
#include "harness/results/junit.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace {

using namespace shatter;

RunContext context() {
  RunContext c;
  c.commit = "0123456789ab";
  c.build_type = "Release";
  c.compiler = "GNU 12.2.0";
  c.flags = "-O3 -DNDEBUG";
  c.cpu_model = "Example CPU";
  c.cores = 2;
  c.date = "2026-11-22T07:00:00Z";
  c.fingerprint = context_fingerprint(c);
  return c;
}

/// A grid of two cells whose per-repetition worst frames and stage times are `base_ms` times `scale`
/// times a noise factor in [1 - noise, 1 + noise] (SplitMix64 `seed`).
GridResult synthetic(int repetitions, double scale, double noise, std::uint64_t seed) {
  GridResult g;
  g.budget_ms = 33.3;
  g.repetitions = repetitions;
  g.frames = 4;
  g.same_seed = true;
  SplitMix64 rng(seed);
  for (const int p : {10, 100}) {
    GridCell c;
    c.prefracture = p;
    c.runtime = 25;
    c.prefracturer = c.fracturer = "plane-slice";
    c.stress = "von-mises";
    for (int k = 0; k < repetitions; ++k) {
      GridSample s;
      s.seed = static_cast<std::uint64_t>(k + 1);
      const double f = scale * (1.0 + noise * (2.0 * rng.uniform() - 1.0));
      s.frame_ms = {0.3 * f, 3.0 * f, 0.4 * f, 0.35 * f};
      s.worst_frame_ms = 3.0 * f;
      s.event_ms = 3.0 * f;
      s.event_frame = 1;
      s.stages_ms[static_cast<std::size_t>(Stage::stress)] = 1.0 * f;
      s.stages_ms[static_cast<std::size_t>(Stage::physics)] = 1.2 * f;
      s.worst_frame_cpu_ms = 2.9 * f;
      s.stages_cpu_ms = s.stages_ms;
      c.samples.push_back(s);
    }
    c.worst_frame_ms = 3.0 * scale;
    g.cells.push_back(c);
  }
  return g;
}

StoredGrid stored(const GridResult& g, const RunContext& ctx, const std::string& name) {
  nlohmann::ordered_json case_block = {{"name", "synthetic"}};
  Result<StoredGrid> s = grid_results_from_json(grid_to_json(g, case_block, ctx), name);
  REQUIRE(s);
  s->path = name;
  return *s;
}

int count_rows(const CompareReport& r, Verdict v) {
  int n = 0;
  for (const ComparisonRow& row : r.rows) n += row.verdict == v ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("compare: identical results pass", "[compare]") {
  const StoredGrid a = stored(synthetic(10, 1.0, 0.05, 1), context(), "a.json");
  const CompareReport r = compare_grids(a, a, {});
  CHECK_FALSE(r.failed());
  CHECK(count_rows(r, Verdict::same) == static_cast<int>(r.rows.size()));
  CHECK(r.warnings.empty());
  StoredGrid varied = a;
  varied.grid.same_seed = false;  // repetitions of different workloads: warned about
  REQUIRE(compare_grids(varied, varied, {}).warnings.size() == 1);
}

TEST_CASE("compare: a 20 % slowdown with 10 repetitions is a regression, on either clock", "[compare]") {
  const StoredGrid a = stored(synthetic(10, 1.0, 0.05, 1), context(), "a.json");
  const StoredGrid b = stored(synthetic(10, 1.2, 0.05, 2), context(), "b.json");
  for (const char* clock : {"cpu", "wall"}) {
    CompareOptions o;
    o.clock = clock;
    const CompareReport r = compare_grids(a, b, o);
    CHECK(r.failed());
    CHECK(count_rows(r, Verdict::regressed) == 6);  // worst frame, stress, physics in each of 2 cells
    for (const ComparisonRow& row : r.rows)
      if (row.verdict == Verdict::regressed) {
        CHECK(row.change > 0.1);
        CHECK(row.p_value < 0.01);
      }
  }
}

TEST_CASE("compare: noise around the same median passes, an improvement passes and is reported", "[compare]") {
  const StoredGrid a = stored(synthetic(10, 1.0, 0.15, 1), context(), "a.json");
  const StoredGrid b = stored(synthetic(10, 1.0, 0.15, 7), context(), "b.json");
  CHECK_FALSE(compare_grids(a, b, {}).failed());
  const StoredGrid faster = stored(synthetic(10, 0.7, 0.05, 3), context(), "c.json");
  const CompareReport r = compare_grids(a, faster, {});
  CHECK_FALSE(r.failed());
  CHECK(count_rows(r, Verdict::improved) >= 2);
  CHECK(compare_markdown(r, {}).find("improved") != std::string::npos);
}

TEST_CASE("compare: with 3 repetitions no timing regression can be shown, and it says so", "[compare]") {
  const StoredGrid a = stored(synthetic(3, 1.0, 0.01, 1), context(), "a.json");
  const StoredGrid b = stored(synthetic(3, 2.0, 0.01, 2), context(), "b.json");
  const CompareReport r = compare_grids(a, b, {});
  CHECK_FALSE(r.failed());
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings[0].find("9 or more repetitions") != std::string::npos);
}

TEST_CASE("compare: mismatched fingerprint, case or a missing cell fail with the reason", "[compare]") {
  const StoredGrid a = stored(synthetic(10, 1.0, 0.05, 1), context(), "a.json");
  RunContext other = context();
  other.compiler = "Clang 16";
  other.fingerprint = context_fingerprint(other);
  const CompareReport r = compare_grids(a, stored(synthetic(10, 1.0, 0.05, 1), other, "b.json"), {});
  CHECK(r.failed());
  REQUIRE(r.mismatches.size() == 1);
  CHECK(r.mismatches[0].find("fingerprints differ") != std::string::npos);

  GridResult fewer = synthetic(10, 1.0, 0.05, 1);
  fewer.cells.pop_back();
  const CompareReport m = compare_grids(a, stored(fewer, context(), "c.json"), {});
  CHECK(m.failed());
  CHECK(m.mismatches.at(0).find("cell 100 x 25") != std::string::npos);

  StoredGrid renamed = a;
  renamed.case_block["name"] = "other";
  CHECK(compare_grids(a, renamed, {}).mismatches.size() == 1);
}

TEST_CASE("compare: accuracy regresses against tolerances, not statistics", "[compare]") {
  const StoredGrid a = stored(synthetic(10, 1.0, 0.05, 1), context(), "a.json");
  StoredGrid b = a;
  b.grid.cells[0].accuracy.prefracture_volume_error = 1e-6;
  b.grid.cells[1].accuracy.runtime_all_closed = false;
  const CompareReport r = compare_grids(a, b, {});
  CHECK(r.failed());
  CHECK(count_rows(r, Verdict::failed) == 2);
  StoredGrid within = a;
  within.grid.cells[0].accuracy.prefracture_volume_error = 5e-10;  // below the 1e-9 tolerance
  CHECK_FALSE(compare_grids(a, within, {}).failed());
}

TEST_CASE("compare: instruction counts regress on the threshold alone", "[compare]") {
  GridResult base = synthetic(1, 1.0, 0.0, 1);
  for (GridCell& c : base.cells)
    for (GridSample& s : c.samples) {
      InstructionCounts counts;
      counts.frames = {1e6, 5e7, 2e6, 2e6};
      counts.worst_frame = 5e7;
      counts.stages[static_cast<std::size_t>(Stage::physics)] = 6e6;
      counts.stages[static_cast<std::size_t>(Stage::stress)] = 4e7;
      s.instructions = counts;
    }
  GridResult slower = base;
  slower.cells[1].samples[0].instructions->stages[static_cast<std::size_t>(Stage::physics)] *= 1.10;
  CompareOptions o;
  o.metric = "instructions";
  const CompareReport same = compare_grids(stored(base, context(), "a"), stored(base, context(), "b"), o);
  CHECK_FALSE(same.failed());
  const CompareReport r = compare_grids(stored(base, context(), "a"), stored(slower, context(), "b"), o);
  CHECK(r.failed());
  REQUIRE(count_rows(r, Verdict::regressed) == 1);
  CHECK(compare_markdown(r, o).find("stage physics") != std::string::npos);
  // Time-only results cannot be compared on instructions.
  CHECK(compare_grids(stored(synthetic(3, 1, 0, 1), context(), "t"), stored(base, context(), "b"), o).failed());
}

TEST_CASE("merge: shards join into the unsharded grid, mismatched shards are refused", "[compare]") {
  const GridResult whole = synthetic(3, 1.0, 0.05, 1);
  GridResult s0 = whole, s1 = whole;
  s0.cells = {whole.cells[0]};
  s1.cells = {whole.cells[1]};
  s0.shard_index = 0;
  s1.shard_index = 1;
  s0.shard_count = s1.shard_count = 2;
  Result<StoredGrid> merged = merge_grids({stored(s1, context(), "s1"), stored(s0, context(), "s0")});
  REQUIRE(merged);
  REQUIRE(merged->grid.cells.size() == 2);
  CHECK(merged->grid.cells[0].prefracture == 10);
  CHECK(merged->grid.cells[1].prefracture == 100);
  CHECK(merged->grid.cells[1].samples[2].worst_frame_ms == whole.cells[1].samples[2].worst_frame_ms);
  CHECK_FALSE(merge_grids({stored(s0, context(), "s0"), stored(s0, context(), "s0b")}));  // a cell twice
  RunContext other = context();
  other.commit = "ffffffffffff";
  const auto bad = merge_grids({stored(s0, context(), "s0"), stored(s1, other, "s1")});
  REQUIRE_FALSE(bad);
  CHECK(bad.error().message.find("commit") != std::string::npos);
  // Shards run on different numbers of threads per event are not one grid.
  GridResult threaded = s1;
  threaded.threads = 2;
  const auto mixed = merge_grids({stored(s0, context(), "s0"), stored(threaded, context(), "s1")});
  REQUIRE_FALSE(mixed);
  CHECK(mixed.error().message.find("threads") != std::string::npos);
  // A file written before worker threads has no "threads": one thread.
  auto older = grid_to_json(threaded, {{"name", "synthetic"}}, context());
  REQUIRE(older.at("threads") == 2);
  older.erase("threads");
  const Result<StoredGrid> read_older = grid_results_from_json(older, "older");
  REQUIRE(read_older);
  CHECK(read_older->grid.threads == 1);
}

TEST_CASE("merge --repetitions: runs of the same cells join their samples, summaries recomputed", "[compare]") {
  // Two runs of 3 repetitions whose worst frames are 3 f: f = 1 +- 0.05 and f = 2 +- 0.05.
  GridResult a = synthetic(3, 1.0, 0.05, 1);
  GridResult b = synthetic(3, 2.0, 0.05, 2);
  a.cells[1].accuracy.runtime_volume_error = 1e-12;
  b.cells[1].accuracy.runtime_volume_error = 3e-12;
  b.cells[1].accuracy.runtime_all_closed = false;
  Result<StoredGrid> joined = merge_grids({stored(a, context(), "a"), stored(b, context(), "b")}, MergeParts::repetitions);
  REQUIRE(joined);
  CHECK(joined->grid.repetitions == 6);
  REQUIRE(joined->grid.cells.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    const GridCell& c = joined->grid.cells[i];
    REQUIRE(c.samples.size() == 6);
    CHECK(c.samples[0].worst_frame_ms == a.cells[i].samples[0].worst_frame_ms);  // a's first, in order
    CHECK(c.samples[3].worst_frame_ms == b.cells[i].samples[0].worst_frame_ms);
    // The median of six: the mean of the third and fourth smallest, i.e. of a's largest and b's smallest.
    double a_max = 0.0, b_min = 1e300;
    for (const GridSample& s : a.cells[i].samples) a_max = std::max(a_max, s.worst_frame_ms);
    for (const GridSample& s : b.cells[i].samples) b_min = std::min(b_min, s.worst_frame_ms);
    CHECK(c.worst_frame_ms == Approx(0.5 * (a_max + b_min)).epsilon(1e-12));
    CHECK(c.frame_ms.count == 24);
  }
  CHECK(joined->grid.cells[1].accuracy.runtime_volume_error == 3e-12);
  CHECK_FALSE(joined->grid.cells[1].accuracy.runtime_all_closed);
  // Not the same cells, or another build: refused, naming the reason.
  GridResult one_cell = b;
  one_cell.cells.pop_back();
  const auto fewer = merge_grids({stored(a, context(), "a"), stored(one_cell, context(), "b")}, MergeParts::repetitions);
  REQUIRE_FALSE(fewer);
  CHECK_THAT(fewer.error().message, Catch::Contains("must hold the same cells"));
  GridResult moved = b;
  moved.cells[1].prefracture = 50;
  const auto other_cell = merge_grids({stored(a, context(), "a"), stored(moved, context(), "b")}, MergeParts::repetitions);
  REQUIRE_FALSE(other_cell);
  CHECK_THAT(other_cell.error().message, Catch::Contains("cell 50 x 25 of b is not in a"));
  RunContext other = context();
  other.compiler = "Clang 14.0.6";
  other.fingerprint = context_fingerprint(other);
  const auto rebuilt = merge_grids({stored(a, context(), "a"), stored(b, other, "b")}, MergeParts::repetitions);
  REQUIRE_FALSE(rebuilt);
  CHECK_THAT(rebuilt.error().message, Catch::Contains("fingerprint"));
}

TEST_CASE("gbench output has Google Benchmark's keys", "[compare]") {
  GridResult g = synthetic(3, 1.0, 0.05, 1);
  // CPU times that differ from the wall times, so a copy of the wall time would show.
  for (GridCell& c : g.cells)
    for (GridSample& s : c.samples) {
      s.worst_frame_cpu_ms = 0.5 * s.worst_frame_ms;
      for (double& t : s.stages_cpu_ms) t *= 0.25;
    }
  const auto j = grid_to_gbench_json(g, "synthetic", context());
  for (const char* key : {"date", "host_name", "executable", "num_cpus", "mhz_per_cpu", "cpu_scaling_enabled", "caches",
                          "library_build_type"})
    CHECK(j.at("context").contains(key));
  int iterations = 0;
  std::map<std::string, int> aggregates;
  std::set<std::pair<std::string, int>> seen;  // (name, repetition_index): unique within the file
  for (const auto& b : j.at("benchmarks")) {
    // What tools/compare.py reads: name, time_unit, real_time, cpu_time, run_type and aggregate_name.
    for (const char* key : {"name", "family_index", "per_family_instance_index", "run_name", "run_type",
                            "repetitions", "threads", "iterations", "real_time", "cpu_time", "time_unit"})
      CHECK(b.contains(key));
    CHECK(b.at("time_unit") == "ns");
    const std::string name = b.at("name");
    if (b.at("run_type") == "iteration") {
      ++iterations;
      REQUIRE(b.contains("repetition_index"));
      CHECK(seen.insert({name, b.at("repetition_index").get<int>()}).second);
    } else {
      ++aggregates[b.at("aggregate_name").get<std::string>()];
      CHECK(seen.insert({name, -1}).second);
      CHECK(name == b.at("run_name").get<std::string>() + "_" + b.at("aggregate_name").get<std::string>());
      CHECK(b.at("aggregate_unit") == (b.at("aggregate_name") == "cv" ? "percentage" : "time"));
    }
  }
  CHECK(iterations == 2 * 3 * 3);  // 2 cells x (worst frame, stress, physics) x 3 repetitions
  for (const char* aggregate : {"mean", "median", "stddev", "cv"}) CHECK(aggregates[aggregate] == 2 * 3);

  // Values: worst frame = one frame (iterations 1), wall and CPU clocks apart; a stage = its time per
  // frame over `frames` iterations; nanoseconds.
  const GridSample& s0 = g.cells[0].samples[0];
  const auto& first = j.at("benchmarks")[0];
  CHECK(first.at("name") == "synthetic/10x25/worst_frame");
  CHECK(first.at("iterations") == 1);
  CHECK(first.at("real_time").get<double>() == Approx(1e6 * s0.worst_frame_ms).epsilon(1e-12));
  CHECK(first.at("cpu_time").get<double>() == Approx(1e6 * s0.worst_frame_cpu_ms).epsilon(1e-12));
  bool stress_found = false;
  for (const auto& b : j.at("benchmarks")) {
    if (b.at("name") != "synthetic/10x25/stress" || b.at("repetition_index") != 0) continue;
    stress_found = true;
    CHECK(b.at("iterations") == g.frames);
    const double stress_ms = s0.stages_ms[static_cast<std::size_t>(Stage::stress)];
    CHECK(b.at("real_time").get<double>() == Approx(1e6 * stress_ms / g.frames).epsilon(1e-12));
    CHECK(b.at("cpu_time").get<double>() == Approx(1e6 * 0.25 * stress_ms / g.frames).epsilon(1e-12));
  }
  CHECK(stress_found);
  // The median aggregate of the worst frame against the repetitions' values.
  std::vector<double> worst;
  for (const GridSample& s : g.cells[0].samples) worst.push_back(1e6 * s.worst_frame_ms);
  std::sort(worst.begin(), worst.end());
  for (const auto& b : j.at("benchmarks"))
    if (b.at("name") == "synthetic/10x25/worst_frame_median") CHECK(b.at("real_time").get<double>() == Approx(worst[1]));

  // Aggregates only: the same aggregates, no iteration entry.
  const auto agg = grid_to_gbench_json(g, "synthetic", context(), true);
  int agg_entries = 0;
  for (const auto& b : agg.at("benchmarks")) {
    CHECK(b.at("run_type") == "aggregate");
    ++agg_entries;
  }
  CHECK(agg_entries == 2 * 3 * 4);
}

TEST_CASE("junit: testsuites, counts and a failure element per failed case, escaped", "[compare]") {
  JunitSuite s{"shatterbench.grid.x", {}};
  s.cases.push_back({"cell 10 x 5", "shatterbench.grid.x", 0.001, {}, {}});
  s.cases.push_back({"cell <100> & 25", "shatterbench.grid.x", 0.002, std::string("worst frame 40 ms > budget \"33\""), {}});
  const std::string xml = junit_xml({s});
  CHECK(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0) == 0);
  CHECK(xml.find("\n<testsuites>\n") != std::string::npos);  // Ant's root: no attributes
  CHECK(xml.find("<testsuite name=\"shatterbench.grid.x\" package=\"shatterbench.grid\" id=\"0\" tests=\"2\" failures=\"1\"") !=
        std::string::npos);
  CHECK(xml.find("name=\"cell &lt;100&gt; &amp; 25\"") != std::string::npos);
  // The message once, as an attribute: no text repeating it.
  CHECK(xml.find("<failure message=\"worst frame 40 ms &gt; budget &quot;33&quot;\" type=\"failure\"/>") != std::string::npos);
  // Every opened element is closed.
  const auto count = [&](const std::string& t) {
    std::size_t n = 0;
    for (auto p = xml.find(t); p != std::string::npos; p = xml.find(t, p + 1)) ++n;
    return n;
  };
  CHECK(count("<testcase ") == 2);
  CHECK(count("</testcase>") == 1);                            // the failed case
  CHECK(xml.find("time=\"0.001000\"/>") != std::string::npos);  // the passed one, self-closed
  CHECK(count("<testsuite ") == count("</testsuite>"));
  CHECK(count("<testsuites>") == 1);
  CHECK(count("</testsuites>") == 1);
}

TEST_CASE("compare --markdown: a pull-request comment, verdict and regressions first, under 65,000 characters",
          "[compare]") {
  // A 50-cell grid (10 pre-fracture x 5 runtime counts) with every stage timed, 9 repetitions; the
  // new run is 30 % slower in its first three cells' stress stage.
  const auto grid = [](double slow, std::uint64_t seed) {
    GridResult g;
    g.budget_ms = 33.3;
    g.repetitions = 9;
    g.frames = 4;
    g.same_seed = true;
    SplitMix64 rng(seed);
    int index = 0;
    for (int p = 10; p <= 100; p += 10)
      for (const int r : {5, 10, 15, 20, 25}) {
        GridCell c;
        c.prefracture = p;
        c.runtime = r;
        c.prefracturer = c.fracturer = "plane-slice";
        c.stress = "von-mises";
        const double cell_slow = index++ < 3 ? slow : 1.0;
        for (int k = 0; k < g.repetitions; ++k) {
          GridSample s;
          s.seed = static_cast<std::uint64_t>(k + 1);
          const double f = 1.0 + 0.02 * (2.0 * rng.uniform() - 1.0);
          s.frame_ms = {0.3 * f, 3.0 * f, 0.4 * f, 0.35 * f};
          s.worst_frame_ms = 3.0 * f;
          s.event_ms = 3.0 * f;
          s.event_frame = 1;
          for (const Stage st : kAllStages) s.stages_ms[static_cast<std::size_t>(st)] = 0.1 * f;
          s.stages_ms[static_cast<std::size_t>(Stage::stress)] = 1.0 * f * cell_slow;
          s.worst_frame_cpu_ms = 2.9 * f;
          s.stages_cpu_ms = s.stages_ms;
          c.samples.push_back(s);
        }
        c.worst_frame_ms = 3.0;
        g.cells.push_back(c);
      }
    return g;
  };
  const StoredGrid base = stored(grid(1.0, 1), context(), "base.json");
  const StoredGrid next = stored(grid(1.3, 2), context(), "new.json");
  const CompareReport report = compare_grids(base, next, {});
  REQUIRE(report.failed());
  CHECK(count_rows(report, Verdict::regressed) == 3);
  REQUIRE(report.rows.size() > 500);
  const std::string comment = compare_comment_markdown(report, {});
  CHECK(comment.size() <= kCommentChars);
  // The verdict, then the regressions, then the folded table.
  const std::size_t verdict = comment.find("**FAIL**: 3 regressed");
  const std::size_t regressions = comment.find("#### Regressions and failures (3)");
  const std::size_t details = comment.find("<details><summary>All ");
  REQUIRE(verdict != std::string::npos);
  REQUIRE(regressions != std::string::npos);
  REQUIRE(details != std::string::npos);
  CHECK(verdict < regressions);
  CHECK(regressions < details);
  CHECK(comment.find("</details>") > details);
  // Every regression is in the regressions table, before the fold.
  const std::string before_fold = comment.substr(0, details);
  std::size_t listed = 0;
  for (std::size_t at = before_fold.find("**regressed**"); at != std::string::npos;
       at = before_fold.find("**regressed**", at + 1))
    ++listed;
  CHECK(listed == 3);
  CHECK_THAT(comment, !Catch::Contains("left out"));  // 50 cells fit whole
  // A tighter limit: the unchanged rows at the end of the folded table are counted instead.
  const std::string tight = compare_comment_markdown(report, {}, 20000);
  CHECK(tight.size() <= 20000);
  CHECK_THAT(tight, Catch::Contains("rows left out to fit a comment") && Catch::Contains("#### Regressions and failures (3)"));
  // A small report is whole: every row folded, nothing left out.
  const StoredGrid small = stored(synthetic(10, 1.0, 0.05, 1), context(), "a.json");
  const std::string whole = compare_comment_markdown(compare_grids(small, small, {}), {});
  CHECK_THAT(whole, Catch::Contains("**PASS**") && Catch::Contains("<details>") && !Catch::Contains("left out") &&
                        !Catch::Contains("#### Regressions"));
}

TEST_CASE("compare: a busier machine is not a regression once normalized by the calibration", "[compare]") {
  const auto with_calibration = [](GridResult g, double calibration) {
    for (GridCell& c : g.cells)
      for (GridSample& s : c.samples) s.calibration_ms = calibration;
    return g;
  };
  const StoredGrid a = stored(with_calibration(synthetic(10, 1.0, 0.03, 1), 5.0), context(), "a.json");
  // Everything 40 % slower, the calibration workload too: the machine, not the code.
  const StoredGrid busy = stored(with_calibration(synthetic(10, 1.4, 0.03, 2), 7.0), context(), "b.json");
  const CompareReport normalized = compare_grids(a, busy, {});
  CHECK(normalized.normalized);
  CHECK_FALSE(normalized.failed());
  CHECK(compare_markdown(normalized, {}).find("+40.0 % slower") != std::string::npos);
  CompareOptions raw;
  raw.normalize = false;
  CHECK(compare_grids(a, busy, raw).failed());
  // One stage 20 % slower on an equally busy machine: still caught.
  GridResult slower = with_calibration(synthetic(10, 1.4, 0.03, 2), 7.0);
  for (GridCell& c : slower.cells)
    for (GridSample& s : c.samples) s.stages_cpu_ms[static_cast<std::size_t>(Stage::physics)] *= 1.2;
  const CompareReport r = compare_grids(a, stored(slower, context(), "c.json"), {});
  CHECK(r.failed());
  CHECK(count_rows(r, Verdict::regressed) == 2);  // physics in both cells
}
