// Checks of a stress model's inputs at the API boundary (declared in stress_model.h).
#include "algorithms/stress/stress_model.h"

#include <cmath>
#include <string>

namespace shatter {

namespace {

Status positive(double value, const char* key) {
  if (std::isfinite(value) && value > 0.0) return {};
  return Error{std::string("material: ") + key + " must be finite and > 0 (got " + std::to_string(value) + ")"};
}

}  // namespace

Status check_material(const Material& m) {
  for (const auto& [value, key] : {std::pair{m.density, "density"}, std::pair{m.young_modulus, "young_modulus"},
                                   std::pair{m.tensile_strength, "tensile_strength"},
                                   std::pair{m.compressive_strength, "compressive_strength"},
                                   std::pair{m.shear_strength, "shear_strength"}})
    if (Status s = positive(value, key); !s) return s;
  if (!(std::isfinite(m.poisson_ratio) && m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5))
    return Error{"material: poisson_ratio must be in (-1, 0.5) (got " + std::to_string(m.poisson_ratio) + ")"};
  return {};
}

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
