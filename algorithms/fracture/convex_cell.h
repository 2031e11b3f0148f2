#pragma once
/// A convex region as a set of half-spaces: the cut plan of a cell-based fracturer (Voronoi), which an
/// exact reference can replay.

#include "algorithms/core/plane.h"

#include <vector>

namespace shatter {

/// The intersection of the negative sides (dot(normal, x - point) <= 0) of its planes. A cell with no
/// plane is the whole space.
struct ConvexCell {
  std::vector<Plane> planes;  ///< bounding half-spaces; the cell lies below each plane
};

}  // namespace shatter
