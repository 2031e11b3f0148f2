#pragma once
/// The finite-element grid of fem-lite: a regular grid of equal box cells over the solid's bounding
/// box, keeping the cells whose centre is inside the solid.
///
/// Design note: every element is the same axis-aligned box, so one element stiffness serves them all
/// (hex_element.h). Cell sizes are chosen per axis so that the grid fits the bounding box exactly (a box
/// solid is then meshed without error), with at least two cells per axis: an 8-node element evaluated
/// at its centre sees no bending stress when it is the only one through the depth. Inside is decided by
/// the generalized winding number (> 0.5) at the cell centre. Only the nodes of kept cells are numbered,
/// once per face-connected component of cells: components that touch only along an edge or at a
/// corner share no node and are solved as separate bodies (a shared node would be a hinge).

#include "algorithms/core/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shatter {

/// The kept cells of a regular grid and their nodes.
struct HexGrid {
  Vec3 origin = Vec3::Zero();              ///< lower corner of the grid (the bounding box's), m
  Vec3 cell = Vec3::Ones();                ///< cell size along x, y, z, m
  std::array<int, 3> counts = {0, 0, 0};   ///< cells along x, y, z
  std::vector<Vec3> nodes;                 ///< #N node positions of the kept cells, m
  /// #E elements: node indices, corner (i, j, k) in {0,1}^3 at position i + 2 j + 4 k.
  std::vector<std::array<std::int32_t, 8>> elements;
  std::vector<Vec3> centres;               ///< #E element centres, m
  std::vector<std::int32_t> node_component; ///< #N face-connected component of each node
  int component_count = 0;                  ///< face-connected components of the kept cells

  /// Volume of one cell, m^3.
  [[nodiscard]] double cell_volume() const { return cell.prod(); }
};

/// The cells along x, y, z of the grid over a box of `extent` (m, longest side > 0) at `resolution`
/// (>= 2): the nearest whole number of cells of the nominal size longest / resolution, at least 2.
std::array<int, 3> hex_grid_counts(const Vec3& extent, int resolution);

/// The largest resolution in [2, `resolution`] whose grid over `solid`'s bounding box has at most
/// `max_cells` cells (`resolution` itself when max_cells is 0, or when it fits; 2 when nothing fits).
int budgeted_resolution(const Mesh& solid, int resolution, int max_cells);

/// Builds the grid over closed, outward `solid` with `resolution` (>= 2) cells along the longest axis
/// of its bounding box. Elements and nodes are numbered component by component (components in the
/// order of their first cell), in x-fastest grid order within one. A solid thinner than a cell can
/// give no element.
HexGrid build_hex_grid(const Mesh& solid, int resolution);

}  // namespace shatter
