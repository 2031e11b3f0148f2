#pragma once
/// What the fracture benchmarks share: the fracturer a row names, and its fracture parameters.

#include "algorithms/fracture/fracturer.h"
#include "algorithms/registry/registries.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

namespace shatter {

/// The fracturer `name` of `registries`; null, with `state` skipped and the error as its message,
/// when the registry cannot make it.
inline std::unique_ptr<Fracturer> fracturer_or_skip(benchmark::State& state, const Registries& registries,
                                                    const std::string& name) {
  auto fracturer = registries.fracturers.create(name);
  if (!fracturer) {
    state.SkipWithError(fracturer.error().message.c_str());
    return nullptr;
  }
  return std::move(*fracturer);
}

/// A benchmark fracture's parameters: `n` fragments, seed 1 (every row of a family the same work).
inline FractureParams benchmark_fracture_params(int n) {
  FractureParams params;
  params.fragments = n;
  params.seed = 1;
  return params;
}

}  // namespace shatter
