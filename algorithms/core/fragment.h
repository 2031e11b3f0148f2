#pragma once
/// A fragment: what every fracturer outputs and what bonds, stress and physics are built on.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh.h"

namespace shatter {

/// One output fragment: a closed mesh and its mass properties (density 1).
struct Fragment {
  Mesh mesh;                 ///< closed, outward, faces tagged surface or cut
  MassProperties mass;       ///< of `mesh`
};

}  // namespace shatter
