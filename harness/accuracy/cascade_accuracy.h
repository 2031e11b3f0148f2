#pragma once
/// The cascade family of `shatterbench accuracy`: a failure cascade run by each stress model against
/// the exact cascade of the same structure, loads and strengths.
///
/// Design note: the stress family times one evaluation of the intact structure, which says nothing
/// about a model that approximates the rounds of a cascade (the windowed models,
/// local_cascade_solver.h). Here each case's structure loses the bonds of the fragment nearest its
/// first impact (the impact's hole), its strengths are scaled so that the exact solve of the holed
/// structure puts its most utilized bond at `overload` (so that a cascade runs: the case's own
/// strengths may break nothing), and `propagate` runs until stable. The reference is the exact
/// cascade of the model the model states as its reference (StressModel::exact_cascade_reference: for
/// the rigid-body-spring models, Eigen's LDL^T per component, every round, with the model's criterion).

#include "algorithms/core/result.h"
#include "algorithms/registry/registries.h"
#include "algorithms/stress/propagation.h"
#include "harness/accuracy/accuracy_point.h"
#include "harness/cases/case.h"

#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// What the cascade sweep runs.
struct CascadeAccuracyOptions {
  /// Registered names; when empty, every registered one. A model that states no exact cascade
  /// reference (StressModel::exact_cascade_reference), built-in or plugin,
  /// is left out: there is nothing to set its cascade against.
  std::vector<std::string> models;
  double overload = 1.5;             ///< the largest utilization of the holed structure's exact solve, > 1
  int repetitions = 3;               ///< timed cascades per point (one solver kept for all), >= 1
};

/// How one cascade's outcome differs from a reference cascade's on the same structure.
struct CascadeComparison {
  int broken = 0;                ///< bonds the cascade broke (given broken included)
  int reference_broken = 0;      ///< bonds the reference broke
  int broken_mismatch = 0;       ///< bonds broken by exactly one of the two
  int falling = 0;               ///< fragments in falling clusters
  int reference_falling = 0;
  int falling_mismatch = 0;      ///< fragments falling in exactly one of the two
  /// broken_mismatch over reference_broken (over 1 when the reference breaks nothing).
  [[nodiscard]] double broken_share() const;
  /// falling_mismatch over reference_falling (over 1 when nothing falls in the reference).
  [[nodiscard]] double falling_share() const;
};

/// Compares `cascade` with `reference`, both on a structure of `nodes` fragments.
CascadeComparison compare_cascades(const PropagationResult& cascade, const PropagationResult& reference, int nodes);

/// Runs the sweep on `c`: every model at its default settings and at each value of each key its
/// settings document with an accuracy sweep (the windowed models' `hops`). time = median time of a
/// whole cascade (`propagate`); error = the larger of `broken_mismatch` (bonds broken by one cascade
/// and not the other, over the bonds the reference breaks) and `falling_mismatch` (fragments falling
/// in one and not the other, over the fragments the reference drops); figures also hold both counts,
/// the rounds, and `round_error` (one round from the reference's first state, largest |sigma -
/// sigma_ref| over the largest sigma_ref). A point whose cascade fails or does not converge holds
/// `failed`. Errors: an unknown model, a structure that cannot be built, a reference that fails.
Result<std::vector<AccuracyPoint>> cascade_accuracy(const Case& c, const CascadeAccuracyOptions& options,
                                                    const Registries& registries);

}  // namespace shatter
