#pragma once
/// Stress models by name ("connection-count", "tresca", "von-mises").

#include "algorithms/core/registry.h"
#include "algorithms/stress/stress_model.h"

namespace shatter {

template <>
inline constexpr std::string_view plugin_kind<StressModel> = "stress model";

/// Name -> stress model factory table.
using StressModelRegistry = Registry<StressModel>;
/// Creates a stress model from its settings.
using StressModelFactory = StressModelRegistry::Factory;

}  // namespace shatter
