#pragma once
/// The Pareto front of (time, error) points: the points no other point beats in both.

#include <span>
#include <vector>

namespace shatter {

/// One measured point: time and error, both "lower is better".
struct TimeError {
  double time = 0.0;   ///< ms, finite
  double error = 0.0;  ///< dimensionless; NaN when the point has no error figure (never on the front)
};

/// #points flags: true when no other point has time <= and error <= with at least one strictly
/// smaller. Equal points are all on the front. A point with a non-finite time or error is never on
/// the front and never dominates another.
std::vector<bool> pareto_front(std::span<const TimeError> points);

}  // namespace shatter
