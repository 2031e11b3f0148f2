// Google Benchmark: what the boundary costs (docs/plugins.md, "What the checks cost").
//
//   build/bin/shatter_benchmarks --benchmark_filter='^(boundary|fracture/(elephant|armadillo).off/(plane-slice|voronoi)/)'
//
// Families, each beside the work it guards:
//   boundary/fracture-check/<mesh>/<fracturer>/<n>  check_fracture_output on one fracture's result,
//                                                   next to fracture/<mesh>/<fracturer>/<n> (the fracture)
//   boundary/stress-check/<model>/<bonds>           check_stress_output on one evaluation of a block
//                                                   wall, next to boundary/stress-evaluate/<model>/<bonds>
//   boundary/import/<asset>/{in-process,child}       read_asset against read_asset_isolated (the import
//                                                   in a limited child) of the same binary glTF
//
// Meshes come from $SHATTER_MESH_DIR or <source>/data/meshes (scripts/fetch-meshes).

#include "algorithms/stress/stress_model.h"
#include "algorithms/assets/read_asset.h"
#include "algorithms/assets/write_fragments_glb.h"
#include "algorithms/fracture/fracture_output_check.h"
#include "algorithms/stress/stress_output_check.h"
#include "benchmarks/benchmark_families.h"
#include "fixtures/structures.h"
#include "harness/cases/isolated_import.h"
#include "harness/cases/load_solid.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace shatter {
namespace {

std::filesystem::path mesh_dir() {
  if (const char* env = std::getenv("SHATTER_MESH_DIR")) return env;
  return std::filesystem::path(SHATTER_SOURCE_DIR) / "data" / "meshes";
}

void fracture_check(benchmark::State& state, const Registries& registries, const Solid& solid,
                    const std::string& algorithm, int n) {
  Result<std::unique_ptr<Fracturer>> fracturer = registries.fracturers.create(algorithm);
  if (!fracturer) {
    state.SkipWithError(fracturer.error().message.c_str());
    return;
  }
  FractureParams params;
  params.fragments = n;
  params.seed = 1;
  Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(solid.mesh, params);
  if (!fragments) {
    state.SkipWithError(fragments.error().message.c_str());
    return;
  }
  std::size_t triangles = 0;
  for (const Fragment& f : *fragments) triangles += f.mesh.triangle_count();
  for (auto _ : state) {
    Status s = check_fracture_output(solid.mesh, *fragments, algorithm);
    if (!s) {
      state.SkipWithError(s.error().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(s);
  }
  state.counters["fragments"] = static_cast<double>(fragments->size());
  state.counters["fragment_triangles"] = static_cast<double>(triangles);
}

/// Block walls of about 1,000 and 10,000 bonds (the stress benchmarks' walls).
const SupportGraph& wall(int bonds) {
  static std::map<int, std::unique_ptr<SupportGraph>> cache;
  auto& slot = cache[bonds];
  if (!slot) slot = std::make_unique<SupportGraph>(bonds <= 1000 ? fixtures::block_wall(23, 22) : fixtures::block_wall(71, 71));
  return *slot;
}

/// One evaluation of `model` on the wall under a point load: timed (`check` false) or its result's
/// check timed (`check` true).
void stress_step(benchmark::State& state, const Registries& registries, const std::string& model, int bonds,
                 bool check) {
  const SupportGraph& g = wall(bonds);
  Result<std::unique_ptr<StressModel>> made = registries.stress_models.create(model);
  if (!made) {
    state.SkipWithError(made.error().message.c_str());
    return;
  }
  std::unique_ptr<StressSolver> solver = (*made)->make_solver(g, Material{});
  Loads loads;
  loads.point_loads.push_back(PointLoad{});
  PointLoad& p = loads.point_loads.front();
  p.node = g.node_count() / 2;
  p.point = g.nodes[static_cast<std::size_t>(p.node)].centroid;
  p.force = Vec3(2e4, 0.0, -2e4);
  Result<StressResult> first = solver->evaluate(loads);
  if (!first) {
    state.SkipWithError(first.error().message.c_str());
    return;
  }
  for (auto _ : state) {
    if (check) {
      Status s = check_stress_output(g, *first, model);
      if (!s) {
        state.SkipWithError(s.error().message.c_str());
        return;
      }
      benchmark::DoNotOptimize(s);
    } else {
      Result<StressResult> r = solver->evaluate(loads);
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["bonds"] = static_cast<double>(g.bond_count());
}

void import(benchmark::State& state, const std::filesystem::path& path, bool child) {
  std::size_t triangles = 0;
  for (auto _ : state) {
    Result<Mesh> mesh = child ? read_asset_isolated(path) : read_asset(path);
    if (!mesh) {
      state.SkipWithError(mesh.error().message.c_str());
      return;
    }
    triangles = mesh->triangle_count();
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

/// A folder of its own for the assets written for the import family, removed at exit.
std::filesystem::path scratch() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / ("shatter_boundary_bench_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] { std::filesystem::remove_all(std::filesystem::temp_directory_path() /
                                                 ("shatter_boundary_bench_" + std::to_string(::getpid()))); });
    return d;
  }();
  return dir;
}

}  // namespace

void register_boundary_benchmarks(const Registries& registries) {
  static std::vector<std::pair<std::string, Solid>> solids;
  for (const std::string name : {"elephant.off", "armadillo.off"}) {
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
    for (const std::string algorithm : {"plane-slice", "voronoi"})
      for (const int n : {5, 25, 100})
        benchmark::RegisterBenchmark(
            ("boundary/fracture-check/" + name + "/" + algorithm + "/" + std::to_string(n)).c_str(),
            [reg, s, algorithm, n](benchmark::State& st) { fracture_check(st, *reg, *s, algorithm, n); })
            ->Unit(benchmark::kMillisecond);
  }
  for (const std::string model : {"connection-count", "von-mises"})
    for (const int bonds : {1000, 10000}) {
      benchmark::RegisterBenchmark(("boundary/stress-evaluate/" + model + "/" + std::to_string(bonds)).c_str(),
                                   [reg, model, bonds](benchmark::State& st) { stress_step(st, *reg, model, bonds, false); })
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("boundary/stress-check/" + model + "/" + std::to_string(bonds)).c_str(),
                                   [reg, model, bonds](benchmark::State& st) { stress_step(st, *reg, model, bonds, true); })
          ->Unit(benchmark::kMillisecond);
    }
  // The shipped textured box, and armadillo (about 50k triangles) written as a binary glTF.
  std::vector<std::pair<std::string, std::filesystem::path>> assets = {
      {"BoxTextured.glb", std::filesystem::path(SHATTER_SOURCE_DIR) / "data" / "assets" / "BoxTextured.glb"}};
  for (const auto& [name, solid] : solids) {
    if (name != "armadillo.off") continue;
    const std::filesystem::path glb = scratch() / "armadillo.glb";
    const Fragment whole{solid.mesh, solid.mass};
    if (Status s = write_fragments_glb(glb, std::span<const Fragment>(&whole, 1)); s) assets.emplace_back("armadillo.glb", glb);
    else std::cerr << "shatter_benchmarks: skipping armadillo.glb: " << s.error().message << "\n";
  }
  for (const auto& [name, path] : assets)
    for (const bool child : {false, true})
      benchmark::RegisterBenchmark(("boundary/import/" + name + "/" + (child ? "child" : "in-process")).c_str(),
                                   [path = path, child](benchmark::State& st) { import(st, path, child); })
          ->Unit(benchmark::kMillisecond);
}

}  // namespace shatter
