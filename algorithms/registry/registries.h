#pragma once
/// The registries a run is given: every fracturer and stress model it may create by name. A program
/// makes one Registries, fills it with register_all() and its own plugins, and passes it to the runs
/// (and to run_cli); nothing is process-wide.

#include "algorithms/fracture/fracturer_registry.h"
#include "algorithms/stress/stress_model_registry.h"

namespace shatter {

/// Every plugin table a run reads.
struct Registries {
  FracturerRegistry fracturers;       ///< "plane-slice", "cgal-clip", ...
  StressModelRegistry stress_models;  ///< "connection-count", "tresca", "von-mises"
};

/// Adds every built-in plugin to `registries` (the one explicit list, register_all.cpp).
void register_all(Registries& registries);

}  // namespace shatter
