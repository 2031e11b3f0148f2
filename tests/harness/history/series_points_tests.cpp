// A stored series as the analysis reads it: runs pooled per commit, and change points told in the
// user's terms (medians before and after, relative change, regression by the metric's direction).

#include "harness/history/series_points.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace shatter;

TEST_CASE("series points: runs of one commit are pooled, in commit order", "[history][series]") {
  const std::vector<SeriesRun> runs = {{"r1", "a", 1, "main", true, {1.0, 3.0}},
                                       {"r2", "a", 1, "main", false, {2.0}},
                                       {"r3", "b", 2, "main", true, {5.0, 7.0}}};
  const std::vector<CommitPoint> points = commit_points(runs);
  REQUIRE(points.size() == 2);
  CHECK(points[0].commit == "a");
  CHECK(points[0].samples == std::vector<double>{1.0, 3.0, 2.0});
  CHECK(points[0].median == 2.0);
  CHECK_FALSE(points[0].passed);  // one run at the commit failed its checks
  CHECK(points[1].median == 6.0);
  CHECK(points[1].passed);
}

TEST_CASE("series points: a step is told by its commit, medians either side and direction", "[history][series]") {
  // 40 commits at 10 (alternating 9.9 and 10.1), then 40 at 12: one step of +20 % at index 40.
  std::vector<SeriesRun> runs;
  for (int i = 0; i < 80; ++i) {
    const double level = i < 40 ? 10.0 : 12.0;
    runs.push_back({"r" + std::to_string(i), "c" + std::to_string(i), i, "main", true, {level + (i % 2 ? 0.1 : -0.1)}});
  }
  const std::vector<CommitPoint> points = commit_points(runs);
  const std::vector<SeriesChange> slower = series_changes(points, Better::lower, ChangePointSettings{});
  REQUIRE(slower.size() == 1);
  CHECK(slower[0].index == 40);
  CHECK(slower[0].commit == "c40");
  CHECK(slower[0].median_before == Approx(10.0));
  CHECK(slower[0].median_after == Approx(12.0));
  CHECK(slower[0].change == Approx(0.2));
  CHECK(slower[0].pvalue < 1e-10);
  CHECK(slower[0].kind == ChangeKind::regression);
  CHECK(series_changes(points, Better::higher, ChangePointSettings{})[0].kind == ChangeKind::improvement);
  CHECK(series_changes(points, Better::none, ChangePointSettings{})[0].kind == ChangeKind::neutral);
}
