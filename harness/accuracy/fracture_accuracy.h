#pragma once
/// The fracture family of `shatterbench accuracy`: every fracturer over its knobs on one solid, timed,
/// and measured against the exact replay of the same cuts plus the conservation figures.

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "harness/accuracy/accuracy_point.h"
#include "harness/cases/load_solid.h"

#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// What the fracture sweep runs.
struct FractureAccuracyOptions {
  std::vector<std::string> fracturers;          ///< registered names; every one with a replay when empty
  std::vector<int> fragments = {5, 25, 100};    ///< requested fragment counts
  std::vector<int> fem_resolutions = {8, 16, 32};  ///< fem-lite's grid resolution knob (cells along the longest axis)
  int repetitions = 3;                          ///< timed runs per point (seed 1 each: the same work), >= 1
  int partition_samples = 500;                  ///< points of the partition test (fracture_metrics)
};

/// The fracturers `accuracy` sweeps by default: every registered one except the reference cgal-clip.
std::vector<std::string> default_accuracy_fracturers();

/// Runs the sweep on `solid` (named `case_name`), hit by `impact` when given. A fracturer or replay
/// that fails at one setting gives a point without error whose figures hold `failed` (the message);
/// an unknown fracturer name is an error.
Result<std::vector<AccuracyPoint>> fracture_accuracy(const std::string& case_name, const Solid& solid,
                                                     const std::optional<Impact>& impact,
                                                     const FractureAccuracyOptions& options);

}  // namespace shatter
