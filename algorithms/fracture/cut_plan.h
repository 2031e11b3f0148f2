#pragma once
/// How a fracturer cut a solid, in a form the exact reference (cgal-clip) replays with exact
/// constructions: the accuracy command measures a fracturer against the replay of its own plan.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/convex_cell.h"

#include <cstdint>
#include <variant>
#include <vector>

namespace shatter {

/// The recursive random-plane schedule of recursive_slicing.h (each cut through the largest piece's
/// centroid, drawn from `seed`), run until `fragments` pieces: plane-slice's own schedule.
struct RecursiveCutSchedule {
  int fragments = 1;         ///< requested pieces, >= 1
  std::uint64_t seed = 1;    ///< seed of the plane draws
};

/// Planes that each cut every piece they cross, in order (m; unit normals).
struct PlaneCuts {
  std::vector<Plane> planes;  ///< in cut order
};

/// Convex cells: fragment k is the parts of (solid ∩ cell k), cells in order (convex_cell.h).
struct CellCuts {
  std::vector<ConvexCell> cells;  ///< in fragment order
};

/// The cuts of one fracture, replayed by cgal-clip's fracture, fracture_by_planes or fracture_by_cells.
using CutPlan = std::variant<RecursiveCutSchedule, PlaneCuts, CellCuts>;

}  // namespace shatter
