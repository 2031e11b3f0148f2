#pragma once
/// Step 5 of the repair: closed shells oriented so that together they bound volumes.

#include "algorithms/repair/repair_surface.h"

namespace shatter::repair {

/// The volumes of a closed surface.
struct VolumeShells {
  bool closed = false;  ///< the surface had no border (else nothing below was done)
  int shells = 0;       ///< connected closed shells
  int cavities = 0;     ///< shells at an odd nesting depth: inward-facing cavities of a volume
};

/// Runs CGAL's orient_to_bound_a_volume (each shell outward when nested in an even number of
/// others, inward otherwise) and volume_connected_components (the shells' nesting levels) on a closed
/// surface without self-intersections.
VolumeShells orient_volumes(SurfaceMesh& surface);

}  // namespace shatter::repair
