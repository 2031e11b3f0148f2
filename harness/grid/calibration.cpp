#include "harness/grid/calibration.h"

#include "algorithms/core/random.h"
#include "harness/pipeline/stage.h"

#include <algorithm>
#include <vector>

namespace shatter {

double calibration_ms() {
  const double start = thread_cpu_ms();
  std::vector<double> v(1u << 16);
  volatile double sink = 0.0;
  for (int round = 0; round < 2; ++round) {
    SplitMix64 rng(static_cast<std::uint64_t>(round) + 1);
    for (double& x : v) x = rng.uniform();
    std::sort(v.begin(), v.end());
    double sum = 0.0;
    for (const double x : v) sum += x * x;
    sink = sink + sum;
  }
  return thread_cpu_ms() - start;
}

}  // namespace shatter
