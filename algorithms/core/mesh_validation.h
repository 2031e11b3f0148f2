#pragma once
/// Validation of an input solid: what a fracturer may assume about its mesh.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <string>

namespace shatter {

/// What validate_solid found and fixed.
struct ValidationReport {
  bool flipped = false;            ///< the mesh was closed but oriented inward; its faces were reversed
  int removed_unused_vertices = 0; ///< vertices no triangle referenced, dropped
  int merged_duplicate_vertices = 0;  ///< vertices with identical coordinates, merged into one
  int split_pinched_vertices = 0;  ///< copies made so that sheets meeting at one vertex each have their own
  int shells = 1;                  ///< connected closed shells, all outward, none inside or crossing another
};

/// Checks that `mesh` is a valid solid and normalises it in place: finite coordinates; no triangle
/// with repeated indices or zero area (exactly collinear corners); every undirected edge shared by
/// exactly two triangles with opposite directions (closed, edge-manifold, consistently oriented);
/// positive volume (an inward mesh is flipped and reported); its shells form a solid without
/// cavities (classify_shells: shells that cross, nest with one orientation or face inward inside
/// nothing are refused, and so, until their fracture is supported, are cavities; a mesh whose
/// outermost shells all face inward is flipped). Unused vertices are dropped and duplicate
/// vertices merged before the checks; a vertex where several sheets of triangles meet at one point
/// then gets one copy per sheet (pinched_vertices.h), so a valid solid is a 2-manifold. `what` names
/// the input in the error message (for example the file name).
Result<ValidationReport> validate_solid(Mesh& mesh, const std::string& what);

/// True when every undirected edge is used by exactly two triangles in opposite directions.
bool is_closed_and_oriented(const Mesh& mesh);

/// True when every coordinate is finite.
bool all_finite(const Mesh& mesh);

}  // namespace shatter
