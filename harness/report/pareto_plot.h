#pragma once
/// Time against error of one family on one case from an accuracy results file, with the Pareto front.

#include "algorithms/core/result.h"
#include "harness/accuracy/accuracy_point.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shatter {

/// Writes `STEM.dat`, `STEM.gp` and `STEM.png` into `folder`: every point of `family` on `case_name`
/// with a time and an error, log-log, one colour and symbol per algorithm, the front joined by a
/// dashed step line and its points labelled with their knob. An error of 0 is drawn at a floor below
/// the smallest non-zero error (said in the title). Error when no point has both a time and an error.
Result<std::string> plot_pareto(const std::vector<AccuracyPoint>& points, const std::string& family,
                                const std::string& case_name, const std::filesystem::path& folder,
                                const std::string& stem);

}  // namespace shatter
