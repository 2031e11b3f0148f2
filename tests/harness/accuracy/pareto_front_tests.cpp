// The Pareto front of (time, error) points, and its grouping per family and case.

#include "harness/accuracy/accuracy_point.h"
#include "harness/accuracy/pareto_front.h"

#include <catch2/catch.hpp>

#include <limits>
#include <vector>

using namespace shatter;

TEST_CASE("pareto: a synthetic set keeps exactly the points nothing beats in both", "[accuracy][pareto]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<TimeError> points = {
      {1.0, 0.5},   // 0 front: fastest
      {2.0, 0.1},   // 1 front
      {3.0, 0.1},   // 2 beaten by 1 (slower, same error)
      {2.5, 0.3},   // 3 beaten by 1
      {5.0, 0.01},  // 4 front: most accurate
      {6.0, 0.01},  // 5 beaten by 4
      {2.0, 0.1},   // 6 equal to 1: both stay
      {0.5, nan},   // 7 no error: never on the front, beats nothing
      {nan, 0.0},   // 8 no time: never on the front
      {1.0, 0.6},   // 9 beaten by 0 (same time, larger error)
  };
  const std::vector<bool> front = pareto_front(points);
  const std::vector<bool> expected = {true, true, false, false, true, false, true, false, false, false};
  CHECK(front == expected);
}

TEST_CASE("pareto: empty and single sets", "[accuracy][pareto]") {
  CHECK(pareto_front(std::vector<TimeError>{}).empty());
  CHECK(pareto_front(std::vector<TimeError>{{3.0, 1.0}}) == std::vector<bool>{true});
}

TEST_CASE("pareto: the front is taken per family and case", "[accuracy][pareto]") {
  std::vector<AccuracyPoint> points(4);
  points[0] = {"fracture", "a", "x", "k", {}, {}, 1.0, 0.1, {}, false};
  points[1] = {"fracture", "b", "x", "k", {}, {}, 9.0, 0.9, {}, false};  // alone in its case: on its front
  points[2] = {"fracture", "a", "y", "k", {}, {}, 2.0, 0.2, {}, false};  // beaten by 0
  points[3] = {"stress", "a", "z", "k", {}, {}, 5.0, std::nullopt, {}, true};  // no error
  mark_pareto_front(points);
  CHECK(points[0].pareto);
  CHECK(points[1].pareto);
  CHECK_FALSE(points[2].pareto);
  CHECK_FALSE(points[3].pareto);
}
