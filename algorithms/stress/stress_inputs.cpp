// Checks of a stress model's inputs at the API boundary (declared in stress_model.h).
#include "algorithms/stress/stress_model.h"

#include <cmath>
#include <string>

namespace shatter {

Status check_loads(const Loads& loads, const SupportGraph& graph) {
  if (!loads.gravity.allFinite()) return Error{"loads: gravity must be finite"};
  for (std::size_t i = 0; i < loads.point_loads.size(); ++i) {
    const PointLoad& p = loads.point_loads[i];
    if (p.node < 0 || p.node >= graph.node_count())
      return Error{"loads: point load " + std::to_string(i) + " refers to fragment " + std::to_string(p.node) +
                   " of " + std::to_string(graph.node_count())};
    if (!p.point.allFinite() || !p.force.allFinite())
      return Error{"loads: point load " + std::to_string(i) + " is not finite"};
  }
  return {};
}

}  // namespace shatter
