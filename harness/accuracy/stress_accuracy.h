#pragma once
/// The stress family of `shatterbench accuracy`: every stress model over its knobs (slab count of the
/// analytic beam and column structures; the spring solver's path, tolerance and iteration cap) on one
/// case, timed, with the error of the bond results against the closed form (beam_reference.h) and
/// against a reference solve of the same structure.

#include "algorithms/core/result.h"
#include "algorithms/registry/registries.h"
#include "harness/accuracy/accuracy_point.h"
#include "harness/cases/case.h"

#include <string>
#include <vector>

namespace shatter {

/// What the stress sweep runs.
struct StressAccuracyOptions {
  std::vector<std::string> models;                 ///< registered names; every one when empty
  std::vector<int> slabs = {8, 16, 32, 64};        ///< slab counts of an analytic structure (default solver)
  int solver_slabs = 32;                           ///< slab count at which the solver knobs are swept
  std::vector<double> cg_tolerances = {1e-3, 1e-6, 1e-9};  ///< CG relative residuals swept (CG forced)
  std::vector<int> cg_iteration_caps = {10, 100};  ///< CG iteration caps swept at tolerance 1e-12
  int repetitions = 3;                             ///< timed evaluations per point, >= 1
};

/// max_i |sigma_i - sigma_ref_i| / max_i sigma_ref_i over the bonds of two results of one structure
/// (the absolute difference when every reference stress is zero).
double sigma_error(const StressResult& r, const StressResult& reference);

/// max_i |sigma_i - sigma_ref_i| / max_i sigma_ref_i over the bonds of two results of one structure
/// (the absolute difference when every reference stress is zero).
double sigma_error(const StressResult& r, const StressResult& reference);

/// Runs the sweep on `c`. An analytic case (classify_beam_case) is rebuilt at each slab count and its
/// headline error is the closed-form error; any other case uses its own pre-fractured structure and its
/// headline error is `solver_error`, against the reference solve (Eigen's LDL^T on the whole system).
/// Models come from `registries`; one that documents the CG keys (cg_only, cg_tolerance,
/// max_iterations) is also swept over `cg_tolerances` and `cg_iteration_caps`.
/// connection-count computes no forces: its points have no error, only the first-failure figures.
/// Errors: an unknown model name, a structure that cannot be built.
Result<std::vector<AccuracyPoint>> stress_accuracy(const Case& c, const StressAccuracyOptions& options,
                                                   const Registries& registries);

}  // namespace shatter
