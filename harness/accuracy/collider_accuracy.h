#pragma once
/// The colliders family of `shatterbench accuracy`: what a collider vertex budget (case key
/// `colliders.vertex_budget`, collider_points.h) costs in shape and saves in time.
///
/// Design note: a budget keeps a subset of a piece's points, so its collider is the hull of fewer
/// points, inside the hull of all of them (the exact path). The error is the volume the
/// budget cuts off, relative to the full hull's, per piece; the time is building every piece's
/// collider (the colliders stage's work). The step's own saving (fewer points scanned per contact) is
/// measured in the grid (docs/pipeline.md), where it depends on the scene.

#include "algorithms/core/result.h"
#include "algorithms/registry/registries.h"
#include "harness/accuracy/accuracy_point.h"
#include "harness/cases/load_solid.h"

#include <string>
#include <vector>

namespace shatter {

/// What the colliders sweep runs.
struct ColliderAccuracyOptions {
  std::vector<int> budgets = {0, 8, 16, 32, 64};  ///< collider vertex budgets; 0 = every hull point
  std::vector<int> fragments = {25, 100};         ///< pieces the solid is cut into
  int repetitions = 3;                            ///< timed builds per point, >= 1
};

/// Cuts `solid` (named `case_name`) with `fracturer` (seed 1) into each count of pieces and measures
/// every budget on those pieces, built as the pipeline builds them (the points that cannot be hull
/// corners dropped first, PhysicsSettings::drop_inner_points), then the exact path (every point, knob
/// `every_point`): time = median build time of all colliders, ms; error = the largest share of a
/// piece's hull volume the collider's points cut off; figures: `pieces`, `max_volume_loss`,
/// `mean_volume_loss` and `mean_points` (collider points per piece, mean). A fracture that fails gives
/// points whose figures hold `failed`.
Result<std::vector<AccuracyPoint>> collider_accuracy(const std::string& case_name, const Solid& solid,
                                                     const std::string& fracturer,
                                                     const ColliderAccuracyOptions& options,
                                                     const Registries& registries);

}  // namespace shatter
