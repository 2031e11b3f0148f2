#include "algorithms/stress/stress_output_check.h"

#include <cmath>
#include <string>
#include <vector>

namespace shatter {

Status check_stress_output(const SupportGraph& graph, const StressResult& result, std::string_view model) {
  const std::string prefix = "stress model '" + std::string(model) + "' returned an invalid result: ";
  if (result.bonds.size() != graph.bonds.size())
    return Error{prefix + std::to_string(result.bonds.size()) + " bond results for " +
                 std::to_string(graph.bonds.size()) + " bonds"};
  for (std::size_t i = 0; i < result.bonds.size(); ++i) {
    const BondStress& b = result.bonds[i];
    const std::pair<const char*, double> magnitudes[] = {{"shear_force", b.shear_force}, {"bending_moment", b.bending_moment},
                                                         {"torsion", b.torsion},         {"sigma", b.sigma},
                                                         {"tau", b.tau},                 {"utilization", b.utilization}};
    if (!std::isfinite(b.normal_force))
      return Error{prefix + "bond " + std::to_string(i) + ": normal_force is not finite"};
    for (const auto& [key, value] : magnitudes)
      if (!std::isfinite(value) || value < 0.0)
        return Error{prefix + "bond " + std::to_string(i) + ": " + key + " is " +
                     (std::isfinite(value) ? "negative" : "not finite")};
  }
  const int nodes = graph.node_count();
  std::vector<char> seen(static_cast<std::size_t>(nodes), 0);
  for (std::size_t c = 0; c < result.falling_clusters.size(); ++c) {
    const std::vector<int>& cluster = result.falling_clusters[c];
    if (cluster.empty()) return Error{prefix + "falling cluster " + std::to_string(c) + " is empty"};
    for (const int node : cluster) {
      if (node < 0 || node >= nodes)
        return Error{prefix + "falling cluster " + std::to_string(c) + " names fragment " + std::to_string(node) +
                     " (the structure has " + std::to_string(nodes) + ")"};
      if (seen[static_cast<std::size_t>(node)]++ != 0)
        return Error{prefix + "fragment " + std::to_string(node) + " is named twice in the falling clusters"};
    }
  }
  if (!result.displacements.empty() && result.displacements.size() != 6 * static_cast<std::size_t>(nodes))
    return Error{prefix + std::to_string(result.displacements.size()) + " displacement values for " +
                 std::to_string(nodes) + " fragments (6 each, or none)"};
  for (std::size_t i = 0; i < result.displacements.size(); ++i)
    if (!std::isfinite(result.displacements[i]))
      return Error{prefix + "displacement " + std::to_string(i) + " is not finite"};
  const SolverReport& r = result.report;
  if (!std::isfinite(r.residual) || r.residual < 0.0 || !std::isfinite(r.tolerance) || r.tolerance < 0.0)
    return Error{prefix + "the solver report's residual or tolerance is not a finite non-negative number"};
  if (r.solves < 0 || r.iterations < 0 || r.unknowns < 0)
    return Error{prefix + "the solver report has a negative count"};
  return {};
}

}  // namespace shatter
