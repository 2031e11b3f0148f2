// How well find_change_points (harness/history/change_points.h) finds a step planted in a noisy series,
// and how often it reports one that is not there. A row is one step size and one noise level over 200
// seeds; each seed's series has 100 points at level 100 that step up by the step size at index 60, with
// normal noise of standard deviation cv x the level at each point. The step is looked for as a CI sees
// it: after every new commit from the step's own (prefix of 61 points) to the 100th, stopping at the
// first prefix whose change points hold one within 2 indices of 60. False alarms are the change points
// of the full series farther than that from 60, and those of a step-free series of the same noise.
// The time of a row is the time of all its seeds (one iteration); the figures are counters
// (docs/history.md, "Detection on synthetic series").
#include "harness/history/change_points.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <span>
#include <vector>

namespace {

using namespace shatter;

constexpr std::size_t series_length = 100;  ///< points per series
constexpr std::size_t step_at = 60;          ///< index of the first value of the planted new level
constexpr std::size_t tolerance = 2;         ///< a change point this many indices from step_at finds the step
constexpr int seed_count = 200;              ///< seeds per row; the step-free series uses seed + 1000
constexpr double base_level = 100.0;         ///< level before the step

/// The setting a CI gate might use: a looser p-value, and no step under 1 % reported.
constexpr ChangePointSettings gate_settings{30, 0.01, 0.01};

/// Standard normal draws from std::mt19937_64 by the Box-Muller transform: the same values on every
/// standard library, which std::normal_distribution does not promise.
class NormalNoise {
 public:
  explicit NormalNoise(std::uint64_t seed) : bits_(seed) {}

  /// The next standard normal value.
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1], so the logarithm is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return radius * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  double uniform() { return static_cast<double>(bits_() >> 11) * 0x1.0p-53; }  // [0, 1), 53 bits

  std::mt19937_64 bits_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

/// series_length values at base_level, times (1 + step) from index `step_from` on (series_length: no
/// step), each with normal noise of standard deviation cv x its level. step and cv are shares (0.05 = 5 %).
std::vector<double> noisy_series(double step, double cv, std::size_t step_from, std::uint64_t seed) {
  NormalNoise noise(seed);
  std::vector<double> series(series_length);
  for (std::size_t i = 0; i < series_length; ++i) {
    const double level = i < step_from ? base_level : base_level * (1.0 + step);
    series[i] = level * (1.0 + cv * noise.next());
  }
  return series;
}

/// Whether `cp` is the planted step (within tolerance of step_at).
bool finds_step(const SeriesChangePoint& cp) {
  return cp.index + tolerance >= step_at && cp.index <= step_at + tolerance;
}

/// What one seed gives.
struct SeedOutcome {
  bool found = false;      ///< a change point near step_at in some prefix up to the full series
  int delay = 0;           ///< commits after the step's own when first found (0: found at once)
  int false_alarms = 0;    ///< change points of the full stepped series not near step_at
  int false_alarms_flat = 0;  ///< change points of the step-free series
  int calls = 0;           ///< find_change_points calls made
};

/// One seed's series under `settings`: the online scan of the stepped series, then both false-alarm counts.
SeedOutcome run_seed(double step, double cv, std::uint64_t seed, const ChangePointSettings& settings) {
  SeedOutcome out;
  const std::vector<double> stepped = noisy_series(step, cv, step_at, seed);
  const std::span<const double> all(stepped);
  for (std::size_t n = step_at + 1; n <= series_length && !out.found; ++n) {
    const std::vector<SeriesChangePoint> cps = find_change_points(all.first(n), settings);
    ++out.calls;
    if (std::any_of(cps.begin(), cps.end(), finds_step)) {
      out.found = true;
      out.delay = static_cast<int>(n - 1 - step_at);
    }
  }
  for (const SeriesChangePoint& cp : find_change_points(all, settings))
    if (!finds_step(cp)) ++out.false_alarms;
  const std::vector<double> flat = noisy_series(0.0, cv, series_length, seed + 1000);
  out.false_alarms_flat = static_cast<int>(find_change_points(flat, settings).size());
  out.calls += 2;
  return out;
}

/// The nearest-rank q-quantile of `values` (the ceil(q x size)-th smallest); NaN when empty.
double nearest_rank(std::vector<int> values, double q) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::max<std::size_t>(rank, 1) - 1];
}

/// One row: a step of state.range(0) % under noise of cv state.range(1) %, over seed_count seeds.
void change_point_detection(benchmark::State& state, ChangePointSettings settings) {
  const double step = static_cast<double>(state.range(0)) / 100.0;
  const double cv = static_cast<double>(state.range(1)) / 100.0;
  std::vector<SeedOutcome> outcomes;
  for (auto _ : state) {
    outcomes.clear();
    for (int seed = 0; seed < seed_count; ++seed)
      outcomes.push_back(run_seed(step, cv, static_cast<std::uint64_t>(seed), settings));
    benchmark::DoNotOptimize(outcomes.data());
  }
  std::vector<int> delays;
  int false_alarms = 0;
  int false_alarms_flat = 0;
  int calls = 0;
  for (const SeedOutcome& o : outcomes) {
    if (o.found) delays.push_back(o.delay);
    false_alarms += o.false_alarms;
    false_alarms_flat += o.false_alarms_flat;
    calls += o.calls;
  }
  const double series = static_cast<double>(outcomes.size());
  const double per_100 = 100.0 / static_cast<double>(series_length);  // each series has series_length points
  state.counters["detection_rate"] = static_cast<double>(delays.size()) / series;
  state.counters["false_alarms_per_100"] = false_alarms * per_100 / series;
  state.counters["false_alarms_per_100_flat"] = false_alarms_flat * per_100 / series;
  state.counters["median_delay"] = nearest_rank(delays, 0.5);
  state.counters["p90_delay"] = nearest_rank(delays, 0.9);
  state.counters["calls"] = calls;
}

}  // namespace

BENCHMARK_CAPTURE(change_point_detection, defaults, ChangePointSettings{})
    ->ArgsProduct({{2, 5, 10, 20}, {1, 2, 5, 10}})->ArgNames({"step_pct", "cv_pct"})->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(change_point_detection, gate, gate_settings)
    ->ArgsProduct({{2, 5, 10, 20}, {1, 2, 5, 10}})->ArgNames({"step_pct", "cv_pct"})->Iterations(1)
    ->Unit(benchmark::kMillisecond);
