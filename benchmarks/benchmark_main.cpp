// shatter_benchmarks: the micro-benchmarks of the kernels (Google Benchmark).
//
//   build/bin/shatter_benchmarks [--benchmark_filter=...] [--benchmark_repetitions=5]
//
// The registries below are what the fracture/ and stress families run: a plugin added here (one
// `register_*` call beside register_all) is benchmarked with the built-ins.

#include "benchmarks/benchmark_families.h"

#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
  shatter::Registries registries;
  shatter::register_all(registries);
  shatter::register_fracture_benchmarks(registries);
  shatter::register_big_mesh_benchmarks(registries);
  shatter::register_attribute_benchmarks(registries);
  shatter::register_collider_benchmarks(registries);
  shatter::register_physics_benchmarks(registries);
  shatter::register_stress_benchmarks(registries);
  shatter::register_boundary_benchmarks(registries);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
