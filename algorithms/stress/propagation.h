#pragma once
/// Failure propagation: break what fails, re-solve what the breaks touched, until nothing fails; then
/// the clusters with no path to an anchor fall.
///
/// Every bond with utilization > 1 breaks in the same round (a round is one static state: the loads are
/// applied at once, so no bond is privileged by the order of a loop). After a round only the
/// components holding an end of a newly broken bond are re-solved; the model warm-starts them from the
/// previous displacements (iterative solver) or refactorises them (direct solver: a break changes the
/// matrix; the ordering and symbolic factor of the intact graph are reused, docs/stress.md section 3a).
/// Components without an anchor are falling clusters and are never solved.

#include "algorithms/stress/stress_model.h"

#include <span>
#include <vector>

namespace shatter {

/// Limits of a cascade.
struct PropagationSettings {
  int max_rounds = 10000;   ///< rounds of breaking before giving up (each round breaks >= 1 bond)
  /// Re-solve every component after each round, not only those a break touched. The answer is the
  /// same (an untouched component's system has not changed); this is the reference the frame
  /// pipeline's no-skip mode runs to prove the partial re-solve result-neutral.
  bool resolve_everything = false;
};

/// The final state of a cascade.
struct PropagationResult {
  StressResult result;                       ///< stresses after the last round, `broken` flags set
  std::vector<std::vector<int>> break_order; ///< bond indices broken in each round, first round first
  int rounds = 0;                            ///< rounds that broke something
  SolverReport report;                       ///< summed over every evaluation of the cascade
};

/// Evaluates the structure of `solver`, breaks failing bonds round by round until stable, and reports
/// the falling clusters of the final state (union-find over the intact bonds). `initially_broken`
/// bonds (e.g. destroyed by an impact) are removed before the first evaluation. The solver keeps its
/// work for the next cascade on the same structure (the next event); the result does not depend on
/// what it solved before.
Result<PropagationResult> propagate(StressSolver& solver, const Loads& loads, std::span<const int> initially_broken = {},
                                    const PropagationSettings& settings = {});

/// The same cascade with a solver of its own for `graph` and `material`, which ends with the call.
Result<PropagationResult> propagate(const StressModel& model, const SupportGraph& graph, const Loads& loads,
                                    const Material& material, std::span<const int> initially_broken = {},
                                    const PropagationSettings& settings = {});

}  // namespace shatter
