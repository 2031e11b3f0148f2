#pragma once
/// A fracturer and a stress model defined outside the library, registered the way a user's program
/// registers its own: one call each, beside register_all.

#include "algorithms/fracture/fracturer_registry.h"
#include "algorithms/stress/stress_model_registry.h"

namespace shatter::test {

/// Registers "parallel-planes": the solid split by n - 1 evenly spaced planes normal to one axis
/// (settings: `axis`, 0 to 2, default 0), which states its cut plan (the planes).
void register_parallel_planes(FracturerRegistry& registry);

/// Registers "scaled-von-mises": von Mises with every utilization multiplied by `factor` (settings:
/// `factor`, in (0, 1000], default 1), so that a bond fails once its von Mises utilization passes 1 / factor.
void register_scaled_von_mises(StressModelRegistry& registry);

}  // namespace shatter::test
