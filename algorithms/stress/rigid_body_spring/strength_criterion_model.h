#pragma once
/// "tresca" and "von-mises": the rigid-body-spring static solve (spring_system.h) with a strength
/// criterion on every bond (strength_criterion.h). Components with no anchor are falling clusters and
/// are never solved (their stiffness matrix is singular); their bonds report zero stress. The model is
/// settings; the work of the solves lives in the solver it makes per structure.

#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/strength_criterion.h"
#include "algorithms/stress/stress_model.h"
#include "algorithms/stress/stress_model_registry.h"

namespace shatter {

/// A rigid-body-spring model judged by one criterion.
class StrengthCriterionModel final : public StressModel {
 public:
  /// The model for `criterion`, with solver `settings`.
  explicit StrengthCriterionModel(Criterion criterion, SpringSolverSettings settings = {})
      : criterion_(criterion), settings_(settings) {}

  [[nodiscard]] std::string_view name() const override {
    return criterion_ == Criterion::tresca ? "tresca" : "von-mises";
  }
  /// A StrengthCriterionSolver (strength_criterion_solver.h) for `graph` and `material`.
  [[nodiscard]] std::unique_ptr<StressSolver> make_solver(const SupportGraph& graph,
                                                          const Material& material) const override;
  /// This criterion with the reference solves (SpringSolverSettings::reference): Eigen's LDL^T per
  /// component, every round.
  [[nodiscard]] std::unique_ptr<StressModel> exact_cascade_reference() const override;

 private:
  Criterion criterion_;
  SpringSolverSettings settings_;
};

/// The documented settings of "tresca" and "von-mises": `tolerance` (SpringSolverSettings::
/// residual_tolerance), `max_iterations` (cg_max_iterations), `cg_tolerance`, and `cg_only` (no block
/// factorised: direct_max_flops < 0). The accuracy command sweeps CG on a model that documents these.
std::vector<SettingDoc> spring_solver_setting_docs();

/// SpringSolverSettings (defaults, with the given keys) from user settings of `model`; an error names
/// the key and its range.
Result<SpringSolverSettings> read_spring_solver_settings(std::string_view model, const PluginSettings& settings);

/// Registers "tresca".
void register_tresca(StressModelRegistry& registry);

/// Registers "von-mises".
void register_von_mises(StressModelRegistry& registry);

}  // namespace shatter
