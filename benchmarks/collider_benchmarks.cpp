// Google Benchmark: building the colliders of a fracture's pieces, with every point of a piece and
// with the points that can be corners of its hull only (PhysicsSettings::drop_inner_points,
// harness/pipeline/physics/outer_points.h), as the pipeline's colliders stage builds them (hulls of
// more than 64 points reduced). The pieces are made once, outside the timing; each iteration builds
// every piece's body in a fresh world (the world's creation is not timed).
//
//   build/bin/shatter_benchmarks --benchmark_filter='^colliders/' --benchmark_repetitions=5
// Rows: colliders/<solid>/<fracturer>/{every-point,outer-points}/<pieces>. The solids: a 2 x 1 x 0.3 m
// slab (a wall's block), and `slab-piece`, one of its 25 plane-slice pieces cut again into the row's
// count (a runtime fracture of a hit fragment: every earlier cut left points on its edges).
// Counters: points per collider before Bullet's hull reduction (mean), pieces.

#include "algorithms/core/primitives.h"
#include "algorithms/core/self_intersection_verdicts.h"
#include "benchmarks/benchmark_families.h"
#include "harness/pipeline/physics/collider_points.h"
#include "harness/pipeline/physics/physics_world.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

using namespace shatter;

namespace {

/// `solid` cut into `n` by `algorithm` with seed 1; empty when the fracturer refuses.
std::vector<Fragment> pieces_of(const Registries& registries, const Mesh& solid, const std::string& algorithm, int n) {
  auto fracturer = registries.fracturers.create(algorithm);
  if (!fracturer) return {};
  FractureParams params;
  params.fragments = n;
  params.seed = 1;
  auto out = (*fracturer)->fracture(solid, params);
  return out ? std::move(*out) : std::vector<Fragment>{};
}

void build_colliders(benchmark::State& state, const std::vector<Fragment>& pieces, bool drop_inner_points) {
  if (pieces.empty()) {
    state.SkipWithError("the fracture failed");
    return;
  }
  PhysicsSettings settings;
  settings.max_hull_vertices = 64;  // as the pipeline builds its world
  settings.drop_inner_points = drop_inner_points;
  for (auto _ : state) {
    state.PauseTiming();
    auto world = std::make_unique<PhysicsWorld>(settings);
    state.ResumeTiming();
    for (const Fragment& piece : pieces) benchmark::DoNotOptimize(world->prepare_fragment(piece, 2400.0));
    state.PauseTiming();
    world.reset();
    state.ResumeTiming();
  }
  double points = 0.0;
  for (const Fragment& piece : pieces)
    points += static_cast<double>(
        collider_vertex_indices(piece.mesh, vertex_planes(piece.mesh), drop_inner_points, 0).size());
  state.counters["points_per_collider"] = points / static_cast<double>(pieces.size());
  state.counters["pieces"] = static_cast<double>(pieces.size());
}

}  // namespace

namespace shatter {

void register_collider_benchmarks(const Registries& registries) {
  const Mesh slab = make_box(Vec3(2.0, 1.0, 0.3));
  const std::vector<Fragment> blocks = pieces_of(registries, slab, "plane-slice", 25);
  const Mesh slab_piece = blocks.empty() ? slab : blocks.front().mesh;
  struct Solid {
    std::string name;
    Mesh mesh;
  };
  for (const Solid& solid : {Solid{"slab", slab}, Solid{"slab-piece", slab_piece}})
    for (const std::string algorithm : {"plane-slice", "voronoi"})
      for (const int n : {25, 100}) {
        // Shared by the two rows of a pair: the same pieces with and without their inner points.
        auto pieces = std::make_shared<const std::vector<Fragment>>(pieces_of(registries, solid.mesh, algorithm, n));
        for (const bool drop : {false, true}) {
          const std::string name = "colliders/" + solid.name + "/" + algorithm + "/" +
                                   (drop ? "outer-points" : "every-point") + "/" + std::to_string(n);
          benchmark::RegisterBenchmark(name.c_str(), [pieces, drop](benchmark::State& state) {
            build_colliders(state, *pieces, drop);
          })->Unit(benchmark::kMillisecond);
        }
      }
}

}  // namespace shatter
