#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

#include "algorithms/stress/rigid_body_spring/strength_criterion_solver.h"

#include <memory>

namespace shatter {

std::unique_ptr<StressSolver> StrengthCriterionModel::make_solver(const SupportGraph& graph,
                                                                  const Material& material) const {
  return std::make_unique<StrengthCriterionSolver>(graph, material, criterion_, settings_);
}

void register_tresca(StressModelRegistry& registry) {
  registry.add("tresca", "rigid-body-spring static solve, Tresca sqrt(s^2 + 4 t^2) on every bond",
               [] { return std::make_unique<StrengthCriterionModel>(Criterion::tresca); });
}

void register_von_mises(StressModelRegistry& registry) {
  registry.add("von-mises", "rigid-body-spring static solve, von Mises sqrt(s^2 + 3 t^2) on every bond",
               [] { return std::make_unique<StrengthCriterionModel>(Criterion::von_mises); });
}

}  // namespace shatter
