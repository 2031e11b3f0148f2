#pragma once
/// The one explicit list of plugins. Adding an algorithm means one line in register_all.cpp.

#include "algorithms/fracture/fracturer_registry.h"
#include "algorithms/stress/stress_model_registry.h"

namespace shatter {

/// Every registry of the library, filled by register_all().
struct Registries {
  FracturerRegistry fracturers;  ///< "plane-slice", "cgal-clip", ...
  StressModelRegistry stress_models;  ///< "connection-count", "tresca", "von-mises"
};

/// Registers every built-in plugin.
void register_all(Registries& registries);

/// The process-wide registries, filled on first use.
const Registries& registries();

}  // namespace shatter
