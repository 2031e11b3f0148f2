#pragma once
/// When the error figures of a fracture make it a valid result: the checks `fracture`, `table` and
/// `grid` apply before they report success (docs/stability.md, "solids and results checked").
///
/// Design note: a command whose own figures show a broken result must not exit 0. The thresholds
/// are far above what the built-in fracturers give on every mesh and case of the test suite (volume
/// error below 1e-9, no misplaced sample point) and far below what a broken result gives (a
/// negative fragment, a missing or doubled one: errors of order 1), so a failed check is a real
/// defect, not noise.

#include "algorithms/fracture/fracturer.h"
#include "harness/metrics/attribute_metrics.h"
#include "harness/metrics/fracture_metrics.h"

#include <string>
#include <vector>

namespace shatter {

/// Thresholds of accept_fracture.
struct FractureAcceptance {
  /// Largest relative volume error |sum V_i - V| / V accepted (dimensionless).
  double max_volume_error = 1e-6;
  /// Largest partition error accepted: the share of sampled points inside the input found in zero
  /// or several fragments (dimensionless). 1 % tolerates a point that round-off places on a cut at
  /// the smallest sample counts the harness uses (100), never a missing or doubled fragment.
  double max_partition_error = 0.01;
  /// Largest UV, normal and cap normal error accepted (attribute_metrics.h; UV units and unit-vector
  /// distances). Exact interpolation gives round-off, about 1e-15; a corner mixed at a wrong
  /// parameter or a wrong source gives errors of the size of a texel (1/4096 = 2.4e-4) or more.
  double max_attribute_error = 1e-6;
};

/// The default acceptance, with the volume error `fracturer` states by design (an approximate method:
/// Fracturer::volume_tolerance, clamped as the host's output check clamps it) as its volume and
/// partition thresholds when that is larger.
FractureAcceptance acceptance_for(const Fracturer& fracturer);

/// The checks `m` fails, one line each without a trailing newline, for example
/// "volume_error 7.9 > 1e-06" or "all_closed: fragment 2: volume -0.49 is not positive"; empty when
/// every check holds: every fragment valid (all_closed), at least one fragment, volume and
/// partition errors within `acceptance`.
std::vector<std::string> failed_fracture_checks(const FractureMetrics& m, const FractureAcceptance& acceptance = {});

/// The attribute checks `a` fails, in the same form ("uv_error 0.01 > 1e-06",
/// "material_errors: 3 faces"); empty when the input carried no attributes or every check holds.
std::vector<std::string> failed_attribute_checks(const AttributeMetrics& a, const FractureAcceptance& acceptance = {});

}  // namespace shatter
