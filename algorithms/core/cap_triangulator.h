#pragma once
/// Constrained Delaunay triangulation of the cut polygons of a slice (the "cap"), after Sloan (1993):
/// incremental Delaunay insertion with exact predicates, constraint recovery by edge flips, and the
/// inside selected by winding number across the constraints. Loops may be many, nested, and may have
/// holes; loops may touch at vertices. Shared by the cut caps of the fracturers, the profiles of
/// prism meshes and the polygon faces of the mesh readers (polygon_triangulation.h).

#include "algorithms/core/mesh.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace shatter {

/// A directed constraint segment between two input points; the region lies to its left.
using CapEdge = std::array<std::int32_t, 2>;

/// Output of triangulate_cap.
struct CapTriangulation {
  /// Triangles over the input point indices, counter-clockwise, covering exactly the points whose
  /// winding number with respect to the directed edges is positive.
  std::vector<Triangle> triangles;
  bool ok = true;        ///< false when the constraints could not be honoured (they cross each other)
  std::string error;     ///< why, when !ok
};

/// The order in which the points enter the Delaunay triangulation.
enum class InsertionOrder {
  bins,               ///< Sloan's bin order: fastest for the scattered points of a cut cap
  randomized_rounds,  ///< shuffled rounds of doubling size, each in bin order: expected O(n log n) for any
                      ///< points, nearly cocircular ones included (the polygon faces of mesh files)
};

/// Triangulates the region to the left of the directed edges. `edges` form closed loops (every point
/// has as many outgoing as incoming edges); outer loops run counter-clockwise, holes clockwise.
/// Points with identical coordinates are treated as one point; points no edge uses are ignored.
/// Pairs of opposite edges on the same segment cancel.
CapTriangulation triangulate_cap(std::span<const Vec2> points, std::span<const CapEdge> edges,
                                 InsertionOrder order = InsertionOrder::bins);

}  // namespace shatter
