// Google Benchmark: the fracture kernels side by side on real meshes of about 1k, 10k and 100k
// triangles: one plane slice (plane-slice and its exact reference cgal-clip), and every registered
// fracturer into 5, 25 and 100 fragments. Error figures ride along as counters, so every time has its accuracy next to it.
//
//   build/bin/shatter_benchmarks [--benchmark_filter=...] [--benchmark_repetitions=5]
// Families: slice/ (plane-slice vs cgal-clip), fracture/ (every fracturer of the registries given to
// register_fracture_benchmarks, so a plugin registered in benchmark_main.cpp is benchmarked), voronoi/ (voronoi vs its exact cell replay;
// `voronoi` breaks a solid it has seen before, `voronoi-first` one it has not, so it pays the input check
// of self_intersection.h every time, as the replay does), self-intersection/ (that check alone).
//
// Meshes come from $SHATTER_MESH_DIR or <source>/data/meshes (scripts/fetch-meshes).

#include "algorithms/core/self_intersection.h"
#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_cells.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"
#include "harness/cases/load_solid.h"
#include "harness/metrics/fracture_metrics.h"
#include "benchmarks/benchmark_families.h"
#include "benchmarks/benchmark_fracturer.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace shatter;

namespace {

std::filesystem::path mesh_dir() {
  if (const char* env = std::getenv("SHATTER_MESH_DIR")) return env;
  return std::filesystem::path(SHATTER_SOURCE_DIR) / "data" / "meshes";
}

/// The meshes of the size ladder: about 1k, 5k, 10k, 50k and 100k triangles.
const std::vector<std::string>& ladder() {
  static const std::vector<std::string> names = {"sphere966.off", "elephant.off", "homer.off", "armadillo.off",
                                                 "refined_elephant.off"};
  return names;
}

/// The exact self-intersection test voronoi and fem-lite run on every input.
void self_intersection(benchmark::State& state, const Solid& solid) {
  bool found = false;
  for (auto _ : state) {
    found = find_self_intersection(solid.mesh).has_value();
    benchmark::DoNotOptimize(found);
  }
  state.counters["triangles"] = static_cast<double>(solid.mesh.triangle_count());
  state.counters["intersects"] = found ? 1.0 : 0.0;
}

void slice_once(benchmark::State& state, const Solid& solid, const std::string& algorithm) {
  const Plane plane{solid.mass.centroid, Vec3(0.3, 0.5, 0.8).normalized()};
  const std::span<const Plane> planes(&plane, 1);
  std::vector<Fragment> fragments;
  for (auto _ : state) {
    auto out = algorithm == "cgal-clip" ? CgalClipFracturer().fracture_by_planes(solid.mesh, planes)
                                        : PlaneSliceFracturer().fracture_by_planes(solid.mesh, planes);
    if (!out) {
      state.SkipWithError(out.error().message.c_str());
      return;
    }
    fragments = std::move(*out);
    benchmark::DoNotOptimize(fragments.data());
  }
  const FractureMetrics m = fracture_metrics(solid.mesh, solid.mass, fragments, 2);
  state.counters["triangles"] = static_cast<double>(solid.mesh.triangle_count());
  state.counters["fragments"] = static_cast<double>(fragments.size());
  state.counters["volume_error"] = m.volume_error;
  state.counters["partition_error"] = m.partition_error;
}

/// Input checks on a solid seen before are remembered (self_intersection_verdicts.h): `again` keeps one
/// memory for every iteration, `first` gives each fracture a new one, so that each iteration is the
/// solid's first fracture.
enum class Visit { again, first };

void fracture_into(benchmark::State& state, const Registries& registries, const Solid& solid,
                   const std::string& algorithm, int n, Visit visit = Visit::again) {
  const std::unique_ptr<Fracturer> fracturer = fracturer_or_skip(state, registries, algorithm);
  if (!fracturer) return;
  FractureParams params = benchmark_fracture_params(n);
  std::vector<Fragment> fragments;
  std::unique_ptr<SelfIntersectionVerdicts> verdicts = std::make_unique<SelfIntersectionVerdicts>();
  for (auto _ : state) {
    if (visit == Visit::first) verdicts = std::make_unique<SelfIntersectionVerdicts>();
    params.verdicts = verdicts.get();
    auto out = fracturer->fracture(solid.mesh, params);
    if (!out) {
      state.SkipWithError(out.error().message.c_str());
      return;
    }
    fragments = std::move(*out);
    benchmark::DoNotOptimize(fragments.data());
  }
  const FractureMetrics m = fracture_metrics(solid.mesh, solid.mass, fragments, n);
  state.counters["triangles"] = static_cast<double>(solid.mesh.triangle_count());
  state.counters["fragments"] = static_cast<double>(fragments.size());
  state.counters["volume_error"] = m.volume_error;
  state.counters["partition_error"] = m.partition_error;
}

/// voronoi's cells replayed exactly: the same sites and bisector planes, corefined by CGAL.
void voronoi_replay(benchmark::State& state, const Solid& solid, int n) {
  FractureParams params;
  params.fragments = n;
  params.seed = 1;
  std::vector<Fragment> fragments;
  for (auto _ : state) {
    auto sites = sample_sites(solid.mesh, params);
    if (!sites) {
      state.SkipWithError(sites.error().message.c_str());
      return;
    }
    std::vector<ConvexCell> cells(sites->size());
    for (int i = 0; i < static_cast<int>(sites->size()); ++i)
      for (int j = 0; j < static_cast<int>(sites->size()); ++j)
        if (i != j) cells[static_cast<std::size_t>(i)].planes.push_back(bisector_plane(*sites, i, j));
    auto out = CgalClipFracturer().fracture_by_cells(solid.mesh, cells);
    if (!out) {
      state.SkipWithError(out.error().message.c_str());
      return;
    }
    fragments = std::move(*out);
  }
  const FractureMetrics m = fracture_metrics(solid.mesh, solid.mass, fragments, n);
  state.counters["triangles"] = static_cast<double>(solid.mesh.triangle_count());
  state.counters["fragments"] = static_cast<double>(fragments.size());
  state.counters["volume_error"] = m.volume_error;
  state.counters["partition_error"] = m.partition_error;
}

}  // namespace

namespace shatter {

void register_fracture_benchmarks(const Registries& registries) {
  static std::vector<std::pair<std::string, Solid>> solids;
  for (const std::string& name : ladder()) {
    Result<Solid> solid = load_solid(mesh_dir() / name);
    if (!solid) {
      std::cerr << "shatter_benchmarks: skipping " << name << ": " << solid.error().message << "\n";
      continue;
    }
    solids.emplace_back(name, std::move(*solid));
  }
  const Registries* reg = &registries;
  for (const auto& [name, solid] : solids) {
    const Solid* s = &solid;
    for (const char* algorithm : {"plane-slice", "cgal-clip"}) {
      const std::string algo = algorithm;
      benchmark::RegisterBenchmark(("slice/" + name + "/" + algo).c_str(),
                                   [s, algo](benchmark::State& st) { slice_once(st, *s, algo); })
          ->Unit(benchmark::kMillisecond);
    }
    for (const std::string& algo : registries.fracturers.names()) {
      for (int n : {5, 25, 100}) {
        benchmark::RegisterBenchmark(("fracture/" + name + "/" + algo + "/" + std::to_string(n)).c_str(),
                                     [reg, s, algo, n](benchmark::State& st) { fracture_into(st, *reg, *s, algo, n); })
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
  for (const auto& [name, solid] : solids) {
    const Solid* s = &solid;
    for (int n : {5, 25, 100}) {
      benchmark::RegisterBenchmark(("voronoi/" + name + "/voronoi/" + std::to_string(n)).c_str(),
                                   [reg, s, n](benchmark::State& st) { fracture_into(st, *reg, *s, "voronoi", n); })
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("voronoi/" + name + "/voronoi-first/" + std::to_string(n)).c_str(),
                                   [reg, s, n](benchmark::State& st) { fracture_into(st, *reg, *s, "voronoi", n, Visit::first); })
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("voronoi/" + name + "/cgal-replay/" + std::to_string(n)).c_str(),
                                   [s, n](benchmark::State& st) { voronoi_replay(st, *s, n); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  for (const auto& [name, solid] : solids) {
    const Solid* s = &solid;
    benchmark::RegisterBenchmark(("self-intersection/" + name).c_str(),
                                 [s](benchmark::State& st) { self_intersection(st, *s); })
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace shatter
