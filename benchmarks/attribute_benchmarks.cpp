// Google Benchmark: what carrying attributes costs each fracturer. The same solid is fractured with
// the same seed twice: once as geometry only and once dressed as a textured asset (flat normals, one
// box-mapped UV set, tangents, a surface and an interior material: surface_mapping.h), so the two rows
// of a pair differ only by the attribute work. The attributed row carries its attribute error figures.
//
//   build/bin/shatter_benchmarks --benchmark_filter='^attributes/' --benchmark_repetitions=5
// Rows: attributes/<mesh>/<fracturer>/{geometry,attributes}/<n>. Compare the medians of a pair. The
// meshes: elephant.off and homer.off whole, and brick-piece, a runtime-sized fragment of a brick.
// attributes/<mesh>/output-floor copies the dressed mesh's corner values once: the least any
// fracture writing its fragments' attributes pays. attributes/<mesh>/<fracturer>/output-floor/<n>
// writes that fracture's fragments' corner values and materials into new arrays: what handing over
// the attributed output costs by itself, beside the pair it belongs to.

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/self_intersection_verdicts.h"
#include "algorithms/core/surface_mapping.h"
#include "harness/cases/load_solid.h"
#include "harness/metrics/attribute_metrics.h"
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

std::filesystem::path attribute_mesh_dir() {
  if (const char* env = std::getenv("SHATTER_MESH_DIR")) return env;
  return std::filesystem::path(SHATTER_SOURCE_DIR) / "data" / "meshes";
}

/// `solid` dressed as a textured asset: box mapping at a tenth of its size per UV unit.
Mesh dressed(const Solid& solid) {
  Mesh mesh = solid.mesh;
  MaterialSlot brick;
  brick.name = "brick";
  apply_box_mapping(mesh, default_cut_uv_scale(mesh) / 10.0, brick);
  prepare_cut_faces(mesh);
  return mesh;
}

void fracture_pair(benchmark::State& state, const Registries& registries, const Mesh& mesh,
                   const std::string& algorithm, int n) {
  const std::unique_ptr<Fracturer> fracturer = fracturer_or_skip(state, registries, algorithm);
  if (!fracturer) return;
  FractureParams params = benchmark_fracture_params(n);
  SelfIntersectionVerdicts verdicts;  // the input check once, as in a game's repeated fractures
  params.verdicts = &verdicts;
  std::vector<Fragment> fragments;
  for (auto _ : state) {
    auto out = fracturer->fracture(mesh, params);
    if (!out) {
      state.SkipWithError(out.error().message.c_str());
      return;
    }
    fragments = std::move(*out);
    benchmark::DoNotOptimize(fragments.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangle_count());
  state.counters["fragments"] = static_cast<double>(fragments.size());
  const AttributeMetrics a = attribute_metrics(mesh, fragments);
  if (!a.measured) return;
  state.counters["uv_error"] = a.uv_error;
  state.counters["normal_error"] = a.normal_error;
  state.counters["cap_normal_error"] = a.cap_normal_error;
  state.counters["material_errors"] = a.material_errors;
}

// The two rows of a pair enter fracture_pair through functions of their own, kept out of line, so that
// a sampling profiler's call stacks tell them apart (docs/attributes.md, "Where the time goes"). The
// empty asm statements keep the compiler from folding the two identical bodies into one.
[[gnu::noinline]] void geometry_row(benchmark::State& state, const Registries& registries, const Mesh& mesh,
                                   const std::string& algorithm, int n) {
  fracture_pair(state, registries, mesh, algorithm, n);
  asm volatile("");
}
[[gnu::noinline]] void attributed_row(benchmark::State& state, const Registries& registries, const Mesh& mesh,
                                     const std::string& algorithm, int n) {
  fracture_pair(state, registries, mesh, algorithm, n);
  asm volatile("" ::: "memory");
}

/// The least a fracture that writes its fragments' attributes pays on `mesh`: its corner values
/// copied once into a new array (every fragment face's values are written once; a fracture adds cut
/// faces to that). Compared with a geometry row it bounds the attributes' cost ratio from below.
void output_floor(benchmark::State& state, const Mesh& mesh) {
  const CornerValues& values = mesh.attributes.corners;
  for (auto _ : state) {
    std::vector<double> copy(values.begin(), values.end());
    benchmark::DoNotOptimize(copy.data());
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(values.size() * sizeof(double));
}

/// The least a fracture of `mesh` by `algorithm` into `n` pays to hand over its fragments' attributes:
/// the fragments' corner values and materials (made once, before the loop) written into new arrays,
/// one per fragment, the previous iteration's freed, as the fracture's own loop does. The attributed
/// row's time over the geometry row's cannot drop below (geometry + this) / geometry while fragments
/// carry their attributes as mesh_attributes.h lays them out.
void fragment_output_floor(benchmark::State& state, const Registries& registries, const Mesh& mesh,
                           const std::string& algorithm, int n) {
  const std::unique_ptr<Fracturer> fracturer = fracturer_or_skip(state, registries, algorithm);
  if (!fracturer) return;
  auto made = fracturer->fracture(mesh, benchmark_fracture_params(n));
  if (!made) {
    state.SkipWithError(made.error().message.c_str());
    return;
  }
  std::vector<MeshAttributes> kept;
  double bytes = 0.0;
  for (const Fragment& f : *made)
    bytes += static_cast<double>(f.mesh.attributes.corners.size() * sizeof(double) +
                                 f.mesh.attributes.materials.size() * sizeof(std::int32_t));
  for (auto _ : state) {
    std::vector<MeshAttributes> written(made->size());
    for (std::size_t i = 0; i < made->size(); ++i) {
      const MeshAttributes& from = (*made)[i].mesh.attributes;
      written[i].corners.assign(from.corners.begin(), from.corners.end());
      written[i].materials.assign(from.materials.begin(), from.materials.end());
    }
    kept = std::move(written);
    benchmark::DoNotOptimize(kept.data());
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = bytes;
}

/// Fragment 0 of a dressed 0.4 x 0.2 x 0.1 m brick pre-fractured by plane-slice into 40.
Result<Mesh> brick_piece(const Registries& registries) {
  Solid brick;
  brick.mesh = make_box(Vec3(0.4, 0.2, 0.1));
  Mesh dressed_brick = dressed(brick);
  auto fracturer = registries.fracturers.create("plane-slice");
  if (!fracturer) return fracturer.error();
  FractureParams params;
  params.fragments = 40;
  params.seed = 1;
  auto fragments = (*fracturer)->fracture(dressed_brick, params);
  if (!fragments) return fragments.error();
  if (fragments->empty()) return Error{"plane-slice gave no fragment"};
  return std::move(fragments->front().mesh);
}

}  // namespace

namespace shatter {

void register_attribute_benchmarks(const Registries& registries) {
  struct Pair {
    std::string name;
    Mesh geometry;
    Mesh attributes;
  };
  static std::vector<Pair> pairs;
  for (const std::string name : {"elephant.off", "homer.off"}) {
    Result<Solid> solid = load_solid(attribute_mesh_dir() / name);
    if (!solid) {
      std::cerr << "shatter_benchmarks: skipping " << name << ": " << solid.error().message << "\n";
      continue;
    }
    pairs.push_back({name, solid->mesh, dressed(*solid)});
  }
  // A runtime-sized piece: one fragment of a dressed brick pre-fractured into 40 (its faces the
  // brick's surface and earlier cut faces), as a game's runtime fracture meets it.
  if (Result<Mesh> piece = brick_piece(registries)) {
    Mesh bare = *piece;
    bare.attributes = MeshAttributes{};
    pairs.push_back({"brick-piece", std::move(bare), std::move(*piece)});
  } else {
    std::cerr << "shatter_benchmarks: skipping brick-piece: " << piece.error().message << "\n";
  }
  const Registries* reg = &registries;
  for (const Pair& pair : pairs) {
    const Mesh* dressed_mesh = &pair.attributes;
    benchmark::RegisterBenchmark(("attributes/" + pair.name + "/output-floor").c_str(),
                                 [dressed_mesh](benchmark::State& st) { output_floor(st, *dressed_mesh); })
        ->Unit(benchmark::kMillisecond);
    for (const std::string& algo : registries.fracturers.names()) {
      for (const int n : {5, 25}) {
        const Mesh* dressed_for_floor = &pair.attributes;
        benchmark::RegisterBenchmark(
            ("attributes/" + pair.name + "/" + algo + "/output-floor/" + std::to_string(n)).c_str(),
            [reg, dressed_for_floor, algo, n](benchmark::State& st) {
              fragment_output_floor(st, *reg, *dressed_for_floor, algo, n);
            })
            ->Unit(benchmark::kMillisecond);
        for (const bool attributed : {false, true}) {
          const Mesh* mesh = attributed ? &pair.attributes : &pair.geometry;
          const std::string row = "attributes/" + pair.name + "/" + algo + "/" +
                                  (attributed ? "attributes/" : "geometry/") + std::to_string(n);
          benchmark::RegisterBenchmark(row.c_str(), [reg, mesh, algo, n](benchmark::State& st) {
            if (mesh->attributes.empty())
              geometry_row(st, *reg, *mesh, algo, n);
            else
              attributed_row(st, *reg, *mesh, algo, n);
          })->Unit(benchmark::kMillisecond);
        }
      }
    }
  }
}

}  // namespace shatter
