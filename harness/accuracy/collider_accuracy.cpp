#include "harness/accuracy/collider_accuracy.h"

#include "harness/pipeline/physics/collider_points.h"
#include "algorithms/core/convex_hull_volume.h"
#include "harness/pipeline/physics/physics_world.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <utility>

namespace shatter {
namespace {

/// The figures of one collider setting over `pieces`.
nlohmann::ordered_json shape_figures(const std::vector<Fragment>& pieces, bool drop_inner_points, int budget,
                                     double& max_loss) {
  double sum_loss = 0.0;
  double sum_points = 0.0;
  max_loss = 0.0;
  for (const Fragment& piece : pieces) {
    const std::vector<Vec3>& all = piece.mesh.vertices;
    const double full = convex_hull_volume(all);
    std::vector<Vec3> kept;
    for (const std::int32_t v : collider_vertex_indices(piece.mesh, vertex_planes(piece.mesh), drop_inner_points, budget))
      kept.push_back(all[static_cast<std::size_t>(v)]);
    // Every point kept is the hull itself (computed again, it could differ in the last bit).
    const double loss = full > 0.0 && kept.size() < all.size()
                            ? std::clamp(1.0 - convex_hull_volume(kept) / full, 0.0, 1.0)
                            : 0.0;
    max_loss = std::max(max_loss, loss);
    sum_loss += loss;
    sum_points += static_cast<double>(kept.size());
  }
  const double n = std::max<double>(1.0, static_cast<double>(pieces.size()));
  return {{"pieces", pieces.size()},
          {"max_volume_loss", max_loss},
          {"mean_volume_loss", sum_loss / n},
          {"mean_points", sum_points / n}};
}

}  // namespace

Result<std::vector<AccuracyPoint>> collider_accuracy(const std::string& case_name, const Solid& solid,
                                                     const std::string& fracturer,
                                                     const ColliderAccuracyOptions& options,
                                                     const Registries& registries) {
  auto f = registries.fracturers.create(fracturer);
  if (!f) return Error{"colliders: " + f.error().message};
  for (const int b : options.budgets)
    if (b != 0 && b < 4) return Error{fmt::format("colliders: a vertex budget must be 0 or >= 4, got {}", b)};
  std::vector<AccuracyPoint> points;
  for (const int n : options.fragments) {
    FractureParams params;
    params.fragments = n;
    params.seed = 1;
    Result<std::vector<Fragment>> pieces = (*f)->fracture(solid.mesh, params);
    // Every budget as the pipeline builds colliders (inner points dropped), and the exact path: every
    // point of the piece, no budget.
    std::vector<std::pair<bool, int>> settings_list;
    for (const int budget : options.budgets) settings_list.emplace_back(true, budget);
    settings_list.emplace_back(false, 0);
    for (const auto& [drop_inner, budget] : settings_list) {
      AccuracyPoint p;
      p.family = "colliders";
      p.case_name = case_name;
      p.algorithm = "hull";
      p.knobs = {{"fragments", n}, {"fracturer", fracturer}, {"vertex_budget", budget},
                 {"drop_inner_points", drop_inner}};
      p.knob = drop_inner ? fmt::format("fragments={} vertex_budget={}", n, budget)
                          : fmt::format("fragments={} every_point", n);
      if (!pieces) {
        p.time_ms = std::numeric_limits<double>::quiet_NaN();
        p.figures = {{"failed", pieces.error().message}};
        points.push_back(std::move(p));
        continue;
      }
      PhysicsSettings settings;
      settings.max_hull_vertices = 64;  // as the pipeline builds its world
      settings.hull_vertex_budget = budget;
      settings.drop_inner_points = drop_inner;
      for (int rep = 0; rep < options.repetitions; ++rep) {
        PhysicsWorld world(settings);
        const auto t0 = std::chrono::steady_clock::now();
        for (const Fragment& piece : *pieces) world.prepare_fragment(piece, 1000.0);
        const auto t1 = std::chrono::steady_clock::now();
        p.samples_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      }
      p.time_ms = median_of(p.samples_ms);
      double max_loss = 0.0;
      p.figures = shape_figures(*pieces, drop_inner, budget, max_loss);
      p.error = max_loss;
      points.push_back(std::move(p));
    }
  }
  return points;
}

}  // namespace shatter
