// Google Benchmark: the physics step of many fracture pieces in contact, the work of the frames after
// a large event (docs/pipeline.md, section 7). A 2 x 2 x 2 m block is cut by plane-slice into the
// row's count (seed 1) and the pieces are put in a world as the pipeline builds it (ground under the
// block, hulls of more than 64 points reduced, gravity, the contact pool sized as the pipeline sizes
// it): they start touching along their cut faces, as an event's new pieces do, the block's top half
// is pushed sideways, and the pile falls apart onto the ground. Each iteration times `steps`
// consecutive steps of a fresh world (the world's creation and its bodies are not timed).
//
//   build/bin/shatter_benchmarks --benchmark_filter='^physics/' --benchmark_repetitions=5
// Rows: physics/pile/<pieces>/<steps>. Counters: ms_per_step (the iteration's time over its
// steps), pairs and touching (overlapping and touching pairs after the last step).

#include "algorithms/core/primitives.h"
#include "benchmarks/benchmark_families.h"
#include "harness/pipeline/physics/physics_world.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

using namespace shatter;

namespace {

void step_pile(benchmark::State& state, const std::vector<Fragment>& pieces, int steps) {
  if (pieces.empty()) {
    state.SkipWithError("the fracture failed");
    return;
  }
  PhysicsSettings settings;
  settings.ground = true;
  settings.ground_z = -1.0;  // the block's bottom face
  settings.max_hull_vertices = 64;
  settings.contact_pool_size = std::clamp(64 * static_cast<int>(pieces.size()), 4096, 65536);
  double stepping = 0.0;
  int pairs = 0;
  int touching = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto world = std::make_unique<PhysicsWorld>(settings);
    for (const Fragment& piece : pieces) {
      const int id = world->add_fragment(piece, 2400.0);
      // The top half pushed sideways at 0.25 m/s (an impulse in proportion to each piece's mass).
      if (piece.mass.centroid.z() > 0.0)
        world->apply_impulse(id, 200.0 * piece.mass.volume * Vec3(3.0, 1.0, 0.0), piece.mass.centroid);
    }
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) world->step();
    stepping += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    pairs = world->overlapping_pairs();
    touching = static_cast<int>(world->touching_pairs().size());
    world.reset();
    state.ResumeTiming();
  }
  const auto iterations = static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.counters["ms_per_step"] = stepping / iterations / static_cast<double>(steps);
  state.counters["pairs"] = pairs;
  state.counters["touching"] = touching;
}

}  // namespace

namespace shatter {

void register_physics_benchmarks(const Registries& registries) {
  const Mesh block = make_box(Vec3(2.0, 2.0, 2.0));
  for (const int n : {250, 500}) {
    auto pieces = std::make_shared<std::vector<Fragment>>();
    if (auto fracturer = registries.fracturers.create("plane-slice")) {
      FractureParams params;
      params.fragments = n;
      params.seed = 1;
      if (auto out = (*fracturer)->fracture(block, params)) *pieces = std::move(*out);
    }
    constexpr int kSteps = 30;
    const std::string name = "physics/pile/" + std::to_string(n) + "/" + std::to_string(kSteps);
    benchmark::RegisterBenchmark(name.c_str(), [pieces](benchmark::State& state) { step_pile(state, *pieces, kSteps); })
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace shatter
