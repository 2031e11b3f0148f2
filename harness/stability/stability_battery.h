#pragma once
/// The stability battery: every fracture hazard on every selected fracturer and every stress hazard on
/// every selected stress model, each in its own forked child with a time limit (docs/stability.md).

#include "algorithms/registry/registries.h"
#include "harness/stability/hazard_outcome.h"

#include <functional>
#include <string>
#include <vector>

namespace shatter {

/// What the battery runs.
struct StabilityOptions {
  std::vector<std::string> fracturers;  ///< registered fracturer names (empty: none)
  std::vector<std::string> models;      ///< registered stress model names (empty: none)
  bool quick = false;                   ///< smaller deep-recursion and chain cases
  double time_limit_s = 60.0;           ///< per case and algorithm, s; past it the child is killed
  std::vector<std::string> hazards;     ///< only these hazard names (empty: all)
};

/// Runs the battery with the plugins of `registries`; `progress` (may be empty) sees each result as it
/// arrives.
std::vector<HazardResult> run_stability(const StabilityOptions& options, const Registries& registries,
                                        const std::function<void(const HazardResult&)>& progress = {});

/// Names of every hazard case, fracture ones first (full, not quick, sizes).
std::vector<std::string> hazard_names();

/// True when no result is CRASH, TIMEOUT or INVALID_OUTPUT.
bool all_valid_or_rejected(const std::vector<HazardResult>& results);

}  // namespace shatter
