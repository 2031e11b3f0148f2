#pragma once
/// The stress hazards of the stability battery (docs/stability.md): extreme stiffness ratios, tiny
/// bonds, no anchor, a very long chain and zero gravity; every output finite, convergence and
/// residual reported.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/stress/stress_model.h"
#include "algorithms/registry/registries.h"
#include "harness/stability/hazard_outcome.h"

#include <string>
#include <vector>

namespace shatter {

/// One stress hazard: a support graph built by hand (a column of blocks) and its loads.
struct StressHazard {
  std::string name;           ///< e.g. "chain-10000"
  std::string description;    ///< one line
  SupportGraph graph;         ///< nodes at density 2400 kg/m^3
  Loads loads;                ///< gravity (m/s^2) and point loads
};

/// The stress hazards. `quick` shortens the long chain (10,000 fragments -> 1,000).
std::vector<StressHazard> stress_hazards(bool quick);

/// Propagates failure on `hazard` with the stress model named `model` twice and checks: every bond
/// figure and displacement finite, the solver converged with a finite residual, both runs equal.
/// The model is created from `registries` with its default settings.
HazardResult run_stress_hazard(const StressHazard& hazard, const std::string& model, const Registries& registries);

}  // namespace shatter
