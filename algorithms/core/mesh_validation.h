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
  int split_pinched_vertices = 0;  ///< copies made so that sheets meeting at one vertex or edge each have their own
  int split_non_manifold_edges = 0;  ///< edges used by 2k > 2 triangles, separated into k manifold sheets
  int shells = 1;                  ///< connected closed shells (outer shells, cavities and islands in them)
  int cavities = 0;                ///< inward shells inside another shell, the cavities (islands in them not counted)
};

/// Normalises `mesh` in place and then applies the acceptance rule (check_solid, solid_check.h) to
/// it. Normalising: unused vertices are dropped and vertices with identical coordinates merged; sheets
/// of triangles that meet at one vertex, or along one edge used by 2k triangles (k each way), get
/// their own copies of those vertices (pinched_vertices.h), so a valid solid is a 2-manifold; a mesh
/// whose outermost shells all face inward is flipped. Solids with cavities are accepted. `what` names
/// the input in the error message (for example the file name); vertex and triangle numbers in it are
/// those of the normalised mesh.
Result<ValidationReport> validate_solid(Mesh& mesh, const std::string& what);

/// True when every undirected edge is used by exactly two triangles in opposite directions.
bool is_closed_and_oriented(const Mesh& mesh);

/// True when every coordinate is finite.
bool all_finite(const Mesh& mesh);

}  // namespace shatter
