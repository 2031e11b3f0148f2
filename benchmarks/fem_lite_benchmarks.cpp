// Google Benchmark: fem-lite's resolution knob and cell budget. fem-lite/beam: time against crack-location error, on a simply
// supported beam [0,4] x [0,0.5] x [0,0.5] m (pinned bottom edges at both ends) hit downward at
// mid-span (1000 N s at (2, 0.25, 0.5), 2 fragments). Counters: the first crack's location error
// |x - 2| / 4 and its normal's angle to the beam axis (degrees).
//
//   build/bin/shatter_benchmarks --benchmark_filter='fem-lite/' --benchmark_repetitions=5

#include "algorithms/core/primitives.h"
#include "algorithms/fracture/fem_lite/fem_lite_fracturer.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace shatter;

namespace {

Aabb region(const Vec3& lo, const Vec3& hi) {
  Aabb box;
  box.extend(lo);
  box.extend(hi);
  return box;
}

void fem_lite_resolution(benchmark::State& state) {
  FemLiteSettings settings;
  settings.resolution = static_cast<int>(state.range(0));
  settings.supports = {region(Vec3(-1, -1, -1), Vec3(0.1, 1, 0.01)), region(Vec3(3.9, -1, -1), Vec3(5, 1, 0.01))};
  const Mesh beam = make_box(Vec3(4, 0.5, 0.5), Vec3(2, 0.25, 0.25));
  FractureParams params;
  params.fragments = 2;
  params.seed = 3;
  params.impact = Impact{Vec3(2, 0.25, 0.5), -Vec3::UnitZ(), 1000.0, 0.0};
  const FemLiteFracturer fem(settings);
  Result<FemLiteAnalysis> analysis = fem.analyse(beam, params);
  for (auto _ : state) {
    analysis = fem.analyse(beam, params);
    benchmark::DoNotOptimize(analysis);
  }
  if (!analysis || analysis->planes.empty()) {
    state.SkipWithError("fem-lite found no crack plane");
    return;
  }
  const Plane& first = analysis->planes.front();
  state.counters["elements"] = analysis->elements;
  state.counters["location_error"] = std::abs(first.point.x() - 2.0) / 4.0;
  state.counters["angle_deg"] = std::acos(std::min(1.0, std::abs(first.normal.normalized().x()))) * 180.0 / M_PI;
  state.counters["residual"] = analysis->solve.residual;
}

}  // namespace

/// A compact piece as the runtime meets it: the column case's 0.5 m slab, free-floating (inertia
/// relief).
Mesh column_slab() { return make_box(Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 3.25)); }

/// The column's hit on its slab: sideways (4000 N s, radius 0.4 m) near a top edge, into 25 fragments.
FractureParams sideways_hit() {
  FractureParams params;
  params.fragments = 25;
  params.seed = 3;
  params.impact = Impact{Vec3(0.25, 0, 3.5), -Vec3::UnitX(), 4000.0, 0.4};
  return params;
}

/// The slab at a resolution: its cells grow as the cube of the resolution, and the time of the direct
/// solve faster still (docs/fem-lite.md, "Cost at runtime").
void fem_lite_compact(benchmark::State& state) {
  FemLiteSettings settings;
  settings.resolution = static_cast<int>(state.range(0));
  const Mesh slab = column_slab();
  const FractureParams params = sideways_hit();
  const FemLiteFracturer fem(settings);
  Result<FemLiteAnalysis> analysis = fem.analyse(slab, params);
  for (auto _ : state) {
    analysis = fem.analyse(slab, params);
    benchmark::DoNotOptimize(analysis);
  }
  if (!analysis) {
    state.SkipWithError(analysis.error().message.c_str());
    return;
  }
  state.counters["elements"] = analysis->elements;
  state.counters["unknowns"] = analysis->solve.free_dofs;
}

BENCHMARK(fem_lite_compact)->Name("fem-lite/slab")->DenseRange(4, 12, 2)->Unit(benchmark::kMillisecond);

/// The same slab under a cell budget (max_cells, resolution 16): time, the resolution it came down to,
/// and what the budget moved against the solve without one (resolution 16, 4,096 cells): the first
/// crack plane's normal (degrees) and its offset along the reference normal (m), and the largest
/// principal stress (relative).
void fem_lite_budget(benchmark::State& state) {
  const Mesh slab = column_slab();
  const FractureParams params = sideways_hit();
  static const Result<FemLiteAnalysis> reference = FemLiteFracturer().analyse(slab, params);
  FemLiteSettings settings;
  settings.max_cells = static_cast<int>(state.range(0));
  const FemLiteFracturer fem(settings);
  Result<FemLiteAnalysis> analysis = fem.analyse(slab, params);
  for (auto _ : state) {
    analysis = fem.analyse(slab, params);
    benchmark::DoNotOptimize(analysis);
  }
  if (!analysis || !reference || analysis->planes.empty() || reference->planes.empty()) {
    state.SkipWithError("fem-lite failed or found no crack plane");
    return;
  }
  const Plane& a = analysis->planes.front();
  const Plane& r = reference->planes.front();
  const Vec3 n = r.normal.normalized();
  state.counters["resolution"] = analysis->resolution;
  state.counters["elements"] = analysis->elements;
  state.counters["first_plane_angle_deg"] = std::acos(std::min(1.0, std::abs(a.normal.normalized().dot(n)))) * 180.0 / M_PI;
  state.counters["first_plane_offset_m"] = std::abs((a.point - r.point).dot(n));
  state.counters["max_principal_rel"] = std::abs(analysis->max_principal - reference->max_principal) / reference->max_principal;
}

BENCHMARK(fem_lite_budget)->Name("fem-lite/slab-budget")->Arg(125)->Arg(216)->Arg(512)->Arg(1000)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(fem_lite_resolution)->Name("fem-lite/beam")->Arg(4)->Arg(8)->Arg(12)->Arg(16)->Arg(24)->Arg(32)
    ->Unit(benchmark::kMillisecond);
