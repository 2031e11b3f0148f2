#pragma once
/// The solver of "tresca" and "von-mises" for one structure: the rigid-body-spring static solve
/// (spring_system.h) with a strength criterion on every bond (strength_criterion.h).
///
/// Design note: everything worth keeping between solves of one structure lives here, for the
/// solver's life, and nowhere else: the systems solved before with their factors and the analysed
/// factors by pattern (SolverMemory, solved_systems.h), each bond's spring and stiffness blocks
/// (bond_stiffness_cache.h: a component solved again is assembled from them, with the same numbers),
/// and the cascade solver (cascade_solver.h) with the intact graph's pattern, block split and
/// factors. The pipeline keeps one solver per standing structure for a whole run, so every event
/// starts with the work of the ones before. Paths are chosen as a solver without history would
/// choose them: a first evaluation, and a cascade's first round (a `previous` without
/// displacements), go per component; the later rounds of a cascade go through the cascade solver.
/// So the results do not depend on what the solver solved before. A round whose `previous` is the
/// cascade solver's own last output (the same displacements, bit for bit, and more bonds broken)
/// continues its rounds and may correct their factors instead of refactorising (cascade_solver.h);
/// any other round starts again from a factorisation.

#include "algorithms/stress/rigid_body_spring/bond_stiffness_cache.h"
#include "algorithms/stress/rigid_body_spring/cascade_solver.h"
#include "algorithms/stress/rigid_body_spring/linear_solve.h"
#include "algorithms/stress/rigid_body_spring/solved_systems.h"
#include "algorithms/stress/strength_criterion.h"
#include "algorithms/stress/stress_model.h"

#include <memory>
#include <span>

namespace shatter {

/// A rigid-body-spring solve of one structure judged by one criterion.
class StrengthCriterionSolver final : public StressSolver {
 public:
  /// A solver for `graph` (which must outlive it unchanged) made of `material`.
  StrengthCriterionSolver(const SupportGraph& graph, const Material& material, Criterion criterion,
                          const SpringSolverSettings& settings);
  ~StrengthCriterionSolver() override;

  [[nodiscard]] const SupportGraph& graph() const override { return graph_; }
  [[nodiscard]] Result<StressResult> evaluate(const Loads& loads) override;
  [[nodiscard]] Result<StressResult> reevaluate(const Loads& loads, const StressResult& previous,
                                                std::span<const int> touched) override;
  /// What the per-component solves kept (tests).
  [[nodiscard]] const SolverMemory& memory() const { return memory_; }
  /// The cascade solver, null before the first round that continues a cascade (tests, benchmarks).
  [[nodiscard]] const CascadeSolver* cascade() const { return cascade_.get(); }

 private:
  const SupportGraph& graph_;
  Material material_;
  Criterion criterion_;
  SpringSolverSettings settings_;
  SolverMemory memory_;                    // before cascade_: the cascade returns its factors to it
  BondStiffnessCache stiffness_;           // the bonds' springs and blocks, from each bond's first solve
  std::unique_ptr<CascadeSolver> cascade_; // made by the first round that continues a cascade
  // The cascade solver's last output: displacements (6 #nodes) and broken flags (#bonds); empty when
  // the last solve went another way.
  std::vector<double> cascade_displacements_;
  std::vector<std::uint8_t> cascade_broken_;
};

}  // namespace shatter
