#pragma once
/// One point of `shatterbench accuracy`: an algorithm at one setting of its knobs on one case, its time
/// and its error figures.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// A measured (time, error) point. Figures beyond the headline error are family specific and kept as
/// JSON (docs/results.md, "Accuracy results JSON").
struct AccuracyPoint {
  std::string family;                ///< "fracture" or "stress"
  std::string case_name;             ///< the case the point was measured on
  std::string algorithm;             ///< registered fracturer or stress model name
  std::string knob;                  ///< the knob setting as text, e.g. "fragments=25 resolution=8"
  nlohmann::ordered_json knobs = nlohmann::ordered_json::object();    ///< the same as an object, e.g. {"fragments": 25, "resolution": 8}
  std::vector<double> samples_ms;    ///< wall time of each repetition, ms
  double time_ms = 0.0;              ///< median of samples_ms
  std::optional<double> error;       ///< the headline error (Pareto axis); empty when the model has none
  nlohmann::ordered_json figures = nlohmann::ordered_json::object();  ///< every error figure, by name
  bool pareto = false;               ///< on the Pareto front of its family and case
};

/// Median of `v` (0 when empty).
double median_of(std::vector<double> v);

/// Sets `pareto` on every point: the front is taken per (family, case_name) over the points with an error.
void mark_pareto_front(std::vector<AccuracyPoint>& points);

}  // namespace shatter
