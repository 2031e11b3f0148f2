#pragma once
/// The check every stress result passes before anything uses it (docs/plugins.md, "What the host
/// checks"): a stress model from a plugin is untrusted, and a built-in's result that fails is a defect.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/result.h"
#include "algorithms/stress/stress_model.h"

#include <string_view>

namespace shatter {

/// Error unless `result` is a well-formed evaluation of `graph`: one BondStress per bond with every
/// figure finite and the magnitudes (shear force, bending moment, torsion, sigma, tau, utilization)
/// >= 0; falling clusters that are non-empty lists of fragment indices of the graph, none named twice;
/// displacements empty or 6 per fragment, all finite; a solver report with finite residual and
/// tolerance and non-negative counts. The message starts with "stress model '<model>' returned an
/// invalid result: " and names the first bond, cluster or value at fault.
Status check_stress_output(const SupportGraph& graph, const StressResult& result, std::string_view model);

}  // namespace shatter
