#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

#include "algorithms/stress/rigid_body_spring/strength_criterion_solver.h"

#include <memory>

namespace shatter {

std::unique_ptr<StressSolver> StrengthCriterionModel::make_solver(const SupportGraph& graph,
                                                                  const Material& material) const {
  return std::make_unique<StrengthCriterionSolver>(graph, material, criterion_, settings_);
}

std::unique_ptr<StressModel> StrengthCriterionModel::exact_cascade_reference() const {
  SpringSolverSettings exact;
  exact.reference = true;
  return std::make_unique<StrengthCriterionModel>(criterion_, exact);
}

std::vector<SettingDoc> spring_solver_setting_docs() {
  return {{"tolerance", "", "1e-06", "(0, 1]", "relative residual |K u - f| / |f| a converged solve may leave (or cg_tolerance, if larger)", {}},
          {"max_iterations", "iterations", "20000", "[1, 1000000000]", "CG iterations per block before giving up", {}},
          {"cg_tolerance", "", "1e-10", "(0, 1]", "relative residual at which CG stops, per block", {}},
          {"cg_only", "", "false", "true or false", "solve every block by CG, factorise none", {}}};
}

Result<SpringSolverSettings> read_spring_solver_settings(std::string_view model, const PluginSettings& settings) {
  const std::vector<SettingDoc> docs = spring_solver_setting_docs();
  const SettingsReader r(model, settings, docs);
  SpringSolverSettings s;
  bool cg_only = false;
  if (Status st = r.check_keys(); !st) return st.error();
  if (Status st = r.number_above("tolerance", 0.0, 1.0, s.residual_tolerance); !st) return st.error();
  if (Status st = r.integer("max_iterations", 1, 1000000000, s.cg_max_iterations); !st) return st.error();
  if (Status st = r.number_above("cg_tolerance", 0.0, 1.0, s.cg_tolerance); !st) return st.error();
  if (Status st = r.flag("cg_only", cg_only); !st) return st.error();
  if (cg_only) s.direct_max_flops = -1.0;
  return s;
}

namespace {

/// Registers the rigid-body-spring model judged by `criterion` under `name`.
void register_criterion(StressModelRegistry& registry, const char* name, const char* description,
                        Criterion criterion) {
  registry.add(name, description, spring_solver_setting_docs(),
               [name, criterion](const PluginSettings& settings) -> Result<std::unique_ptr<StressModel>> {
                 Result<SpringSolverSettings> s = read_spring_solver_settings(name, settings);
                 if (!s) return s.error();
                 return std::unique_ptr<StressModel>(std::make_unique<StrengthCriterionModel>(criterion, *s));
               });
}

}  // namespace

void register_tresca(StressModelRegistry& registry) {
  register_criterion(registry, "tresca", "rigid-body-spring static solve, Tresca sqrt(s^2 + 4 t^2) on every bond",
                     Criterion::tresca);
}

void register_von_mises(StressModelRegistry& registry) {
  register_criterion(registry, "von-mises",
                     "rigid-body-spring static solve, von Mises sqrt(s^2 + 3 t^2) on every bond", Criterion::von_mises);
}

}  // namespace shatter
