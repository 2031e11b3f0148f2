#pragma once
/// "tresca-local" and "von-mises-local": the models "tresca" and "von-mises" with cascade rounds solved
/// on a window around their breaks (local_cascade_solver.h). A single evaluation is the exact one; a
/// cascade is an approximation of size `hops` (and `exact_start`), reported against the exact cascade by `shatterbench
/// accuracy --family cascade`.

#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/strength_criterion.h"
#include "algorithms/stress/stress_model.h"
#include "algorithms/stress/stress_model_registry.h"

namespace shatter {

/// The rigid-body-spring model with windowed cascade rounds, judged by one criterion.
class LocalCascadeModel final : public StressModel {
 public:
  /// The default window: 4 bonds around each break (docs/stress.md, section 6).
  static constexpr int kDefaultHops = 4;

  /// With `exact_start`, a cascade's start (its given breaks) is solved exactly, not on a window.
  LocalCascadeModel(Criterion criterion, SpringSolverSettings settings, int hops, bool exact_start = false)
      : criterion_(criterion), settings_(settings), hops_(hops), exact_start_(exact_start) {}

  [[nodiscard]] std::string_view name() const override {
    return criterion_ == Criterion::tresca ? "tresca-local" : "von-mises-local";
  }
  /// A LocalCascadeSolver (local_cascade_solver.h) for `graph` and `material`.
  [[nodiscard]] std::unique_ptr<StressSolver> make_solver(const SupportGraph& graph,
                                                          const Material& material) const override;
  /// The whole-structure model of this criterion with the reference solves (StrengthCriterionModel).
  [[nodiscard]] std::unique_ptr<StressModel> exact_cascade_reference() const override;
  /// Bonds around a break whose nodes a cascade round solves again.
  [[nodiscard]] int hops() const { return hops_; }
  /// Whether a cascade's start is solved exactly.
  [[nodiscard]] bool exact_start() const { return exact_start_; }

 private:
  Criterion criterion_;
  SpringSolverSettings settings_;
  int hops_;
  bool exact_start_;
};

/// Registers "tresca-local" and "von-mises-local".
void register_local_cascade_models(StressModelRegistry& registry);

}  // namespace shatter
