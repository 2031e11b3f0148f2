#pragma once
/// The winding number of a closed mesh at many points, answered from a grid of cells where no
/// triangle comes near, and by WindingNumberQuery elsewhere.
///
/// Design note: off a closed surface (one whose directed edges cancel, so that it bounds) the winding
/// number is an integer that changes only across the surface. A uniform grid over the mesh's box marks
/// every cell within one cell of some triangle's box; the cells left unmarked are surface-free and so
/// are the faces between two of them, so each 6-connected region of unmarked cells has one winding
/// number. It is computed once per region, at the centre of the region's first cell, by the exact
/// tree (WindingNumberQuery); a point in an unmarked cell gets its region's value, a point in a marked
/// cell (near the surface) the tree's. The margin of one cell keeps a point that rounding places in
/// the neighbouring cell far from every triangle, in the same region. On an open mesh (its winding
/// number varies continuously off the surface) or a small one every point goes to the tree.
///
/// Cost: building the tree, then O(#F) to mark the cells (about one per triangle) and label the
/// regions, and one tree query per region of at least kMinRegionCells cells (smaller ones stay with
/// the tree, which bounds the queries on a mesh of many pockets). A query in an unmarked cell is a
/// lookup. Memory: the tree's, plus 4 bytes per cell.

#include "algorithms/core/mesh.h"
#include "algorithms/core/winding_number.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shatter {

/// Winding number of one mesh at many points (see the design note); the same integer as
/// WindingNumberQuery off the surface of a closed mesh, and its exact value elsewhere.
class WindingNumberCells {
 public:
  /// Builds the tree and, for a closed mesh of at least kMinTriangles triangles, the cells.
  explicit WindingNumberCells(const Mesh& mesh);

  /// Winding number at `q` (dimensionless); exactly 0 outside bounds().
  double operator()(const Vec3& q) const;

  /// Bounding box of the triangles' corners, m.
  [[nodiscard]] const Aabb& bounds() const { return tree_.bounds(); }

  /// Number of grid cells (0 when every point goes to the tree).
  [[nodiscard]] std::size_t cell_count() const { return region_of_cell_.size(); }

  /// True when a point in this cell is answered by a lookup (test hook: the cell of `q` is unmarked
  /// and its region has a value).
  [[nodiscard]] bool answered_by_cells(const Vec3& q) const;

  /// Meshes below this many triangles get no cells (the tree alone is as fast).
  static constexpr std::size_t kMinTriangles = 2048;
  /// Regions of fewer cells get no value of their own.
  static constexpr int kMinRegionCells = 8;

 private:
  /// The cell index of `q` (inside bounds()), or -1.
  [[nodiscard]] std::int64_t cell_of(const Vec3& q) const;

  WindingNumberQuery tree_;
  std::array<int, 3> dims_{0, 0, 0};
  Vec3 origin_ = Vec3::Zero();          // the box's lowest corner, m
  double cell_ = 0.0;                   // side of a cell, m
  std::vector<std::int32_t> region_of_cell_;  // -1: marked or too small a region
  std::vector<double> region_value_;          // winding number of each region
};

}  // namespace shatter
