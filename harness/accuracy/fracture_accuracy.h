#pragma once
/// The fracture family of `shatterbench accuracy`: every fracturer over its knobs on one solid, timed,
/// and measured against the exact replay of the same cuts plus the conservation figures.

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/registry/registries.h"
#include "harness/accuracy/accuracy_point.h"
#include "harness/cases/load_solid.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// What the fracture sweep runs.
struct FractureAccuracyOptions {
  std::vector<std::string> fracturers;          ///< registered names; default_accuracy_fracturers() when empty
  std::vector<int> fragments = {5, 25, 100};    ///< requested fragment counts
  /// Values swept for a setting key, replacing the plugin's own SettingDoc::accuracy_sweep (e.g.
  /// "resolution" -> {8, 16}); a key no fracturer sweeps is ignored.
  std::map<std::string, std::vector<double>, std::less<>> sweeps;
  int repetitions = 3;                          ///< timed runs per point (seed 1 each: the same work), >= 1
  int partition_samples = 500;                  ///< points of the partition test (fracture_metrics)
};

/// The fracturers `accuracy` sweeps by default: every registered one except the exact references
/// (Fracturer::exact_reference).
std::vector<std::string> default_accuracy_fracturers(const Registries& registries);

/// The accuracy knobs of fracturer `name`: each documented setting with an accuracy sweep, in the
/// order documented, with the values swept (from `sweeps` when it names the key); empty when it has
/// none. Each knob is swept on its own, the other settings at their defaults.
std::vector<std::pair<std::string, std::vector<double>>> accuracy_knobs(
    const Registries& registries, const std::string& name,
    const std::map<std::string, std::vector<double>, std::less<>>& sweeps);

/// Runs the sweep on `solid` (named `case_name`), hit by `impact` when given. A fracturer or replay
/// that fails at one setting gives a point without error whose figures hold `failed` (the message);
/// an unknown fracturer name, or a knob value its settings refuse, is an error. Each fracturer runs at
/// every fragment count, and at every value of each of its accuracy knobs (accuracy_knobs) when it has any.
Result<std::vector<AccuracyPoint>> fracture_accuracy(const std::string& case_name, const Solid& solid,
                                                     const std::optional<Impact>& impact,
                                                     const FractureAccuracyOptions& options,
                                                     const Registries& registries);

}  // namespace shatter
