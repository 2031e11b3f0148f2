#pragma once
/// Settings of the fem-lite fracturer: plain data, every field with a unit and a default.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/core/material.h"

#include <vector>

namespace shatter {

/// The largest resolution fem-lite accepts (memory of the direct solve grows about as resolution^4).
inline constexpr int kFemLiteMaxResolution = 128;
/// The largest cell budget fem-lite accepts: the cells of the finest grid.
inline constexpr int kFemLiteMaxCells = kFemLiteMaxResolution * kFemLiteMaxResolution * kFemLiteMaxResolution;

/// Settings of the fem-lite fracturer (plain data; every field has a default).
struct FemLiteSettings {
  /// Cells along the longest axis of the solid's bounding box, in [2, kFemLiteMaxResolution];
  /// default 16. The other axes get the nearest whole number of cells of the same size, at least 2.
  /// The knob that trades time for accuracy.
  int resolution = 16;
  /// The most cells the grid over the solid's bounding box may have, in [0, kFemLiteMaxCells]; 0 (the
  /// default) sets no budget. With a budget the resolution is lowered, one step at a time, until the
  /// grid fits (never below 2): a compact piece, whose cells grow as the cube of the resolution, then
  /// costs at most the budget's solve, while a long thin one keeps its resolution. A piece with no cell
  /// centre inside it at the lowered resolution (a thin-walled one) gets the next finer grid that has
  /// one, up to `resolution`: its few cells inside are the solve's size. An approximation
  /// beyond `resolution`'s: a named option, off by default (docs/fem-lite.md, "Cost at runtime").
  int max_cells = 0;
  /// Elastic constants and strengths (default: concrete).
  Material material;
  /// Gravitational acceleration, m/s^2, world frame; default none.
  Vec3 gravity = Vec3::Zero();
  /// Regions (m, world) whose grid nodes are fixed in all three directions; default none, in which
  /// case the model is solved free-floating by inertia relief (see fem_loads.h).
  std::vector<Aabb> supports;
  /// Contact time of the impact, s, > 0; the impact force is impulse / contact_time. Default one
  /// frame at 60 Hz.
  double contact_time = 1.0 / 60.0;
  /// Smallest distance between a new crack's element centre and an earlier crack plane, in cells
  /// (the cell's size along the earlier plane's normal), >= 0; default 1.
  double crack_spacing = 1.0;
  /// Smallest piece a crack plane may cut off, as a share of the mean fragment volume (the solid's
  /// volume / the requested count), in [0, 1); default 0.01. A plane that would leave a smaller
  /// piece (a sliver along an earlier plane or the surface) is skipped; 0 allows any piece.
  double min_piece_share = 0.01;
};

/// Error (naming the key) unless every field is finite and in range.
Status check_fem_lite_settings(const FemLiteSettings& settings);

}  // namespace shatter
