// The gate on the history (harness/history/history_gate.h) on series whose answer is known by
// construction: planted steps in the newest commits, noise alone, an acknowledged step, deterministic
// figures.

#include "harness/history/calibration_scaling.h"
#include "harness/history/history_gate.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace shatter;

namespace {

/// `commits` commits of `samples` samples each, N(level, (cv level)^2), the level multiplied by
/// `factor` from commit `step_at` on.
std::vector<CommitPoint> series(int commits, int samples, double cv, int step_at, double factor, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<CommitPoint> points;
  for (int c = 0; c < commits; ++c) {
    const double level = 100.0 * (c >= step_at ? factor : 1.0);
    std::vector<SeriesRun> runs(1);
    runs[0].commit = "c" + std::to_string(c);
    runs[0].commit_time = c;
    for (int s = 0; s < samples; ++s) runs[0].samples.push_back(level * (1.0 + cv * noise(rng)));
    const std::vector<CommitPoint> p = commit_points(runs);
    points.push_back(p.front());
  }
  return points;
}

}  // namespace

TEST_CASE("history gate: a step in the newest commit regresses, noise does not", "[history][gate]") {
  const HistoryGateSettings settings;
  int regressed = 0, same = 0, improved = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const SeriesVerdict slower = judge_newest(series(20, 5, 0.01, 19, 1.10, seed), 0, Better::lower, "ms", settings);
    regressed += slower.verdict == GateVerdict::regressed;
    CHECK(slower.change == Approx(0.10).margin(0.03));
    CHECK(slower.baseline_size == 19);
    const SeriesVerdict flat = judge_newest(series(20, 5, 0.01, 99, 1.0, seed), 0, Better::lower, "ms", settings);
    same += flat.verdict == GateVerdict::same;
    const SeriesVerdict faster = judge_newest(series(20, 5, 0.01, 19, 0.90, seed), 0, Better::lower, "ms", settings);
    improved += faster.verdict == GateVerdict::improved;
  }
  CHECK(regressed == 20);
  CHECK(same == 20);
  CHECK(improved == 20);
}

TEST_CASE("history gate: a direction decides what a move is", "[history][gate]") {
  const HistoryGateSettings settings;
  const auto up = series(20, 5, 0.01, 19, 1.10, 3);
  CHECK(judge_newest(up, 0, Better::higher, "", settings).verdict == GateVerdict::improved);
  CHECK(judge_newest(up, 0, Better::lower, "", settings).verdict == GateVerdict::regressed);
}

TEST_CASE("history gate: a step a few commits ago stays a regression until acknowledged", "[history][gate]") {
  const HistoryGateSettings settings;
  const auto points = series(30, 5, 0.01, 27, 1.15, 5);  // stepped 2 commits before the newest
  const SeriesVerdict before_ack = judge_newest(points, 0, Better::lower, "ms", settings);
  CHECK(before_ack.verdict == GateVerdict::regressed);
  CHECK(before_ack.note.find("stepped at c27") != std::string::npos);
  CHECK(before_ack.baseline_size == 27);
  // Acknowledged at the step: the newest is judged against the commits since it, the new level.
  const SeriesVerdict after_ack = judge_newest(points, 27, Better::lower, "ms", settings);
  CHECK(after_ack.verdict == GateVerdict::same);
  CHECK(after_ack.baseline_size == 2);
}

TEST_CASE("history gate: the baseline is the last stable segment", "[history][gate]") {
  HistoryGateSettings settings;
  // An old step of +20 % at commit 10, long accepted by time (more than `recent` commits ago): the
  // baseline is the segment since it, so the newest at that level is the same, not a regression.
  const auto points = series(40, 5, 0.01, 10, 1.20, 9);
  const SeriesVerdict v = judge_newest(points, 0, Better::lower, "ms", settings);
  CHECK(v.verdict == GateVerdict::same);
  CHECK(v.baseline_first == 10);
  CHECK(v.base_median == Approx(120.0).epsilon(0.01));
}

TEST_CASE("history gate: deterministic figures are judged by thresholds alone", "[history][gate]") {
  const HistoryGateSettings settings;
  auto points = series(10, 1, 0.0, 99, 1.0, 1);  // one value per commit, no noise
  CHECK(judge_newest(points, 0, Better::lower, "", settings).verdict == GateVerdict::same);
  points.back().samples = {110.0};
  points.back().median = 110.0;
  CHECK(judge_newest(points, 0, Better::lower, "", settings).verdict == GateVerdict::regressed);
  // Below the absolute floor (error figures near rounding): never a regression, whatever the ratio.
  for (CommitPoint& p : points) p.samples = {p.median = 1e-15};
  points.back().samples = {points.back().median = 3e-15};
  CHECK(judge_newest(points, 0, Better::lower, "", settings).verdict == GateVerdict::same);
}

TEST_CASE("history gate: small changes of small stages and the first commit", "[history][gate]") {
  const HistoryGateSettings settings;
  // A 20 % slower stage of 10 microseconds: 2 microseconds, under the 0.01 ms floor.
  auto points = series(20, 5, 0.001, 19, 1.2, 4);
  for (CommitPoint& p : points) {
    for (double& s : p.samples) s *= 1e-4;
    p.median *= 1e-4;
  }
  CHECK(judge_newest(points, 0, Better::lower, "ms", settings).verdict == GateVerdict::same);
  CHECK(judge_newest(series(1, 5, 0.01, 99, 1.0, 1), 0, Better::lower, "ms", settings).verdict == GateVerdict::no_baseline);
}

TEST_CASE("history gate: settings out of range name their flag", "[history][gate]") {
  HistoryGateSettings s;
  s.alpha = 0.0;
  const Status bad = check_history_gate_settings(s);
  REQUIRE_FALSE(bad);
  CHECK(bad.error().message.find("--alpha") == 0);
  CHECK(check_history_gate_settings(HistoryGateSettings{}));
}

TEST_CASE("history gate: the prediction test against the commit medians", "[history][gate]") {
  const std::vector<double> base = {1.0, 2.0, 3.0};  // mean 2, s 1, n 3: t with 2 degrees of freedom
  CHECK(prediction_pvalue(2.0, base) == Approx(1.0));
  // t = 4.302653 is the 0.975 quantile of Student's t with 2 degrees of freedom: p = 0.05.
  CHECK(prediction_pvalue(2.0 + 4.302653 * std::sqrt(4.0 / 3.0), base) == Approx(0.05).epsilon(1e-5));
  CHECK(prediction_pvalue(2.0 - 4.302653 * std::sqrt(4.0 / 3.0), base) == Approx(0.05).epsilon(1e-5));
  const std::vector<double> flat = {5.0, 5.0, 5.0, 5.0};
  CHECK(prediction_pvalue(5.0, flat) == 1.0);
  CHECK(prediction_pvalue(5.1, flat) == 0.0);
}

TEST_CASE("history gate: a run on a busier machine is judged per calibration", "[history][gate]") {
  // The same work timed on a machine half as fast: twice the time, twice the calibration.
  std::vector<SeriesRun> runs = {{"r1", "c1", 1, "main", true, {1.0, 1.0}}, {"r2", "c2", 2, "main", true, {2.0, 2.0}}};
  RunCalibrations calibration = {{"r1", {10.0, 10.0}}, {"r2", {20.0, 20.0}}};
  REQUIRE(normalize_by_calibration(runs, calibration));
  CHECK(runs[0].samples == std::vector<double>{1.5, 1.5});  // scaled to the median calibration, 15
  CHECK(runs[1].samples == std::vector<double>{1.5, 1.5});
  // A run without one calibration per sample: nothing changes.
  std::vector<SeriesRun> partial = {{"r1", "c1", 1, "main", true, {1.0, 1.0}}, {"r3", "c3", 3, "main", true, {2.0}}};
  CHECK_FALSE(normalize_by_calibration(partial, calibration));
  CHECK(partial[1].samples == std::vector<double>{2.0});
}
