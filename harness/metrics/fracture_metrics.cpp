#include "harness/metrics/fracture_metrics.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/random.h"
#include "algorithms/core/shell_classification.h"
#include "algorithms/core/winding_number_cells.h"

#include <fmt/core.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace shatter {
namespace {

// |value - reference| / reference, guarded: 0 without a positive reference, the largest finite
// double when the value itself is not finite (a broken fragment must not read as a perfect one).
double relative_error(double value, double reference) {
  if (!std::isfinite(value)) return std::numeric_limits<double>::max();
  if (!(reference > 0.0) || !std::isfinite(reference)) return 0.0;
  const double error = std::abs(value - reference) / reference;
  return std::isfinite(error) ? error : std::numeric_limits<double>::max();
}

/// Why `fragment` is not a valid solid, or "" when it is: the rule every input solid passes
/// (mesh_validation.h, shell_classification.h), except that a fragment may hold cavities.
std::string fragment_problem(const Fragment& fragment) {
  const double volume = fragment.mass.volume;
  if (fragment.mesh.empty()) return "empty";
  if (!all_finite(fragment.mesh)) return "a non-finite coordinate";
  if (!is_closed_and_oriented(fragment.mesh)) return "not closed and consistently oriented";
  if (!std::isfinite(volume) || !(volume > 0.0)) return "volume " + fmt::format("{:.6g}", volume) + " is not positive";
  const ShellClassification shells = classify_shells(fragment.mesh);
  if (shells.verdict == SolidVerdict::invalid) return shells.reason;
  if (shells.inverted) return "faces inward";
  if (Status s = check_attributes(fragment.mesh, "attributes"); !s) return s.error().message;
  return {};
}

struct PartitionResult {
  int samples = 0;
  int errors = 0;
};

// Samples up to `wanted` points inside `input` and counts those inside zero or several fragments.
// The input's winding numbers come first and its structure is freed; then the fragments are taken
// one at a time, so that no more than one fragment's structure is held at once.
PartitionResult sample_partition(const Mesh& input, std::span<const Fragment> fragments,
                                 const FractureMetricsOptions& options) {
  PartitionResult result;
  const int wanted = options.partition_samples;
  if (wanted <= 0 || input.empty()) return result;

  struct Sample {
    Vec3 point;
    long expected = 0;    // how often the input covers the point
    long containing = 0;  // fragments holding it
  };
  std::vector<Sample> samples;
  {
    // Most samples lie far from every surface: a lookup answers them (winding_number_cells.h).
    const WindingNumberCells inside_input(input);
    const Aabb& box = inside_input.bounds();
    SplitMix64 rng(options.seed);
    const long long max_draws = static_cast<long long>(wanted) * std::max(1, options.max_draws_per_sample);
    for (long long draw = 0; draw < max_draws && static_cast<int>(samples.size()) < wanted; ++draw) {
      const Vec3 p = rng.point_in(box.min, box.max);
      // An input made of overlapping shells covers a point several times; the fragments must cover it
      // as often as the input does (once, for an ordinary solid).
      const long expected = std::lround(inside_input(p));
      if (expected >= 1) samples.push_back({p, expected, 0});
    }
  }
  for (const Fragment& fragment : fragments) {
    const Aabb fragment_box = bounding_box(fragment.mesh);
    // Culling: outside a closed fragment's box the point is outside the fragment.
    if (std::none_of(samples.begin(), samples.end(), [&](const Sample& s) { return fragment_box.contains(s.point); }))
      continue;
    const WindingNumberCells inside_fragment(fragment.mesh);
    for (Sample& s : samples)
      if (s.containing <= s.expected && inside_fragment.bounds().contains(s.point) && inside_fragment(s.point) > 0.5)
        ++s.containing;
  }
  result.samples = static_cast<int>(samples.size());
  for (const Sample& s : samples) result.errors += s.containing != s.expected ? 1 : 0;
  return result;
}

}  // namespace

FractureMetrics fracture_metrics(const Mesh& input, const MassProperties& input_mass,
                                 std::span<const Fragment> fragments, int requested,
                                 const FractureMetricsOptions& options) {
  assert(options.partition_samples >= 0);
  FractureMetrics metrics;
  metrics.fragment_count = static_cast<int>(fragments.size());
  metrics.requested = requested;

  double volume_sum = 0.0;
  double surface_sum = 0.0;
  double repair_sum = 0.0;
  double min_volume = std::numeric_limits<double>::infinity();
  for (const Fragment& fragment : fragments) {
    volume_sum += fragment.mass.volume;
    surface_sum += tagged_area(fragment.mesh, FaceTag::surface);
    repair_sum += tagged_area(fragment.mesh, FaceTag::repair);
    min_volume = std::min(min_volume, fragment.mass.volume);
    if (metrics.all_closed) {
      const std::string problem = fragment_problem(fragment);
      metrics.all_closed = problem.empty();
      if (!problem.empty())
        metrics.fragment_problem = "fragment " + std::to_string(&fragment - fragments.data()) + ": " + problem;
    }
  }
  metrics.volume_error = relative_error(volume_sum, input_mass.volume);
  // Like with like: the input's own surface against the fragments' surface faces, the faces repair
  // added against the fragments' repair faces.
  metrics.area_error = std::max(relative_error(surface_sum, tagged_area(input, FaceTag::surface)),
                                relative_error(repair_sum, tagged_area(input, FaceTag::repair)));
  // std::min skips NaN volumes (comparisons with NaN are false); all-NaN leaves infinity.
  metrics.min_fragment_volume = fragments.empty() || !std::isfinite(min_volume) ? 0.0 : min_volume;

  const PartitionResult partition = sample_partition(input, fragments, options);
  metrics.partition_samples = partition.samples;
  metrics.partition_error =
      partition.samples > 0 ? static_cast<double>(partition.errors) / partition.samples : 0.0;
  return metrics;
}

}  // namespace shatter
