#pragma once
/// The check every fracture result passes before anything uses it: what a fracturer returns is
/// untrusted when it comes from a plugin, and a defect when a built-in's fails it (docs/plugins.md,
/// "What the host checks").
///
/// Design note: the check reads only what the result holds and recomputes what it claims (each
/// fragment's volume, the volumes' sum), in one linear pass per fragment, so a result that would crash
/// or mislead a later stage (an index out of range, a short tag array, a NaN, an open fragment, mass
/// properties that are not its mesh's, a missing or an extra piece) is refused here with the first
/// thing found, never dereferenced first.

#include "algorithms/core/fragment.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/fracture_limits.h"

#include <string_view>
#include <vector>

namespace shatter {

/// Thresholds of check_fracture_output, with their defaults.
struct FractureOutputLimits {
  /// Most fragments accepted (the documented fragment limit, docs/limits.md).
  int max_fragments = kMaxFragments;
  /// Largest relative volume error |sum V_i - V| / V accepted (dimensionless): the acceptance rule's
  /// (harness/metrics/fracture_acceptance.h), far above the built-ins' round-off (below 1e-9).
  double max_volume_error = 1e-6;
  /// Largest relative difference between a fragment's stated mass properties and its mesh's
  /// (dimensionless, against the input's volume and size): the same integrals give round-off only.
  double max_mass_error = 1e-9;
};

/// The most volume error a fracturer may state (Fracturer::volume_tolerance): a tenth of the input's.
inline constexpr double kMaxStatedVolumeTolerance = 0.1;

/// The default limits, with the volume error a fracturer stated (clamped to [0,
/// kMaxStatedVolumeTolerance]; not a finite number counts as 0) when that is above the default's.
FractureOutputLimits limits_with_stated_tolerance(double stated);

/// Error unless `fragments` is a valid fracture of `input` (a closed solid of positive volume): at
/// least one and at most `limits.max_fragments` fragments; in each, finite vertices, every index in
/// range and no repeated corner, one tag of a known kind per triangle, attributes consistent with
/// check_attributes, closed and consistently oriented, a finite positive volume, and stated mass
/// properties (volume, centroid, inertia) equal to its mesh's within `limits.max_mass_error`; and the
/// volumes summing to the input's within `limits.max_volume_error`. The message starts with
/// "fracturer '<algorithm>' returned an invalid result: " and names the first fragment and triangle
/// at fault.
Status check_fracture_output(const Mesh& input, const std::vector<Fragment>& fragments, std::string_view algorithm,
                             const FractureOutputLimits& limits = {});

}  // namespace shatter
