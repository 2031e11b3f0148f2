#pragma once
/// The fracture hazards of the stability battery (docs/stability.md): awkward cuts, extreme scales and
/// positions, slivers and plates, deep recursion, and defective inputs; and the checks every output
/// must pass.

#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/registry/registries.h"
#include "harness/stability/hazard_outcome.h"

#include <string>
#include <vector>

namespace shatter {

/// One fracture hazard: an input mesh (not yet validated) and how it is fractured.
struct FractureHazard {
  std::string name;               ///< e.g. "cut-through-vertices"
  std::string description;        ///< one line
  Mesh mesh;                      ///< the raw input; validate_solid runs first, as for a file
  /// Exact planes, cut in order. A fracturer that cuts by given planes (Fracturer::plane_cutting) cuts
  /// by them; the others fracture every piece of the exact cut, made by the first registered fracturer
  /// that cuts by given planes (plane_cutter, capable_fracturer.h).
  std::vector<Plane> planes;
  FractureParams params;          ///< fragments and seed when there are no planes
  bool refracture = false;        ///< fracture every fragment again with `params` (fragments of fragments)
  /// A fracturer may refuse this case (a non-manifold solid, a fragment count past a documented
  /// limit); on every other case a refusal of the validated solid is REFUSED_VALID_INPUT, a failure.
  bool may_refuse = false;
};

/// The fracture hazards. `quick` shrinks the deep-recursion cases (1,000 fragments -> 100).
std::vector<FractureHazard> fracture_hazards(bool quick);

/// Tolerances of the fracture checks.
struct FractureCheckLimits {
  double volume_error = 1e-6;     ///< relative |sum V_i - V| / V
  double partition_error = 0.02;  ///< share of sample points in zero or several fragments
  int partition_samples = 400;    ///< points sampled for the partition error
};

/// Runs `hazard` on the fracturer named `algorithm` twice (determinism) and checks the output: every
/// fragment closed, oriented and finite, volume and partition error within `limits`, both runs equal
/// bit for bit. Runs in the calling process: the battery isolates it (isolated_run.h).
/// The fracturer is created from `registries` with its default settings.
HazardResult run_fracture_hazard(const FractureHazard& hazard, const std::string& algorithm,
                                 const Registries& registries, const FractureCheckLimits& limits = {});

}  // namespace shatter
