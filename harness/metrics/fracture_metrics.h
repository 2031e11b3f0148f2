#pragma once
/// Error figures of one fracture (DESIGN.md section 6): how well the fragments reproduce the input
/// solid. Every figure is finite and dimensionless except min_fragment_volume; 0 is perfect.
///
/// Design note: the volume error alone cannot see fragments that overlap in one place and leave a gap
/// in another, so the partition error samples points inside the input and asks, by winding number,
/// how many fragments contain each. Its cost is #draws x (input triangles + triangles of the
/// fragments whose bounding box holds the point); culling by fragment bounding box keeps the second
/// term near one fragment's size instead of the whole fragment set.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh.h"
#include "algorithms/fracture/fracturer.h"

#include <cstdint>
#include <span>
#include <string>

namespace shatter {

/// Settings of fracture_metrics.
struct FractureMetricsOptions {
  /// Points inside the input to test for the partition error (>= 0; 0 skips the test).
  int partition_samples = 2000;
  /// Seed of the sampling (SplitMix64); same seed, same figures.
  std::uint64_t seed = 12345;
  /// Draws in the input's bounding box allowed per wanted sample before giving up (a thin input
  /// fills little of its box); the test then uses the inside points it found.
  int max_draws_per_sample = 50;
};

/// Error figures of a set of fragments against the solid they came from.
struct FractureMetrics {
  /// |sum V_i - V| / V (dimensionless). 0 when the input volume V is not positive (no reference);
  /// the largest finite double when a fragment volume is not finite.
  double volume_error = 0.0;
  /// Every fragment is non-empty, finite, closed and consistently oriented, with positive volume,
  /// and its shells form a solid (classify_shells: outward shells that neither cross nor nest with
  /// one orientation; cavities allowed), and its attributes are consistent (check_attributes). True
  /// for an empty fragment list.
  bool all_closed = true;
  /// Why the first invalid fragment fails all_closed ("fragment 3: not closed and consistently
  /// oriented"), empty when all_closed.
  std::string fragment_problem;
  /// Share of the sampled points inside the input (winding number rounding to k >= 1) that lie
  /// inside a number of fragments other than k, in [0, 1]; 0 when no point was sampled. For an
  /// ordinary solid k = 1: a point in zero or several fragments is an error. An input of overlapping
  /// shells (k = 2 where two overlap) must be covered as often by the fragments.
  double partition_error = 0.0;
  /// Relative error of the fragments' area against the input's, tag by tag (dimensionless): the larger of
  /// |sum of surface-tagged area - input's surface-tagged area| / input's surface-tagged area and the same
  /// for repair-tagged faces (faces that mesh repair added; 0 when the input has none). Cut faces are
  /// excluded: they are new surface, not input surface. 0 when the input has no area.
  double area_error = 0.0;
  /// Smallest fragment volume, m^3 (slivers show here); 0 when there is no fragment.
  double min_fragment_volume = 0.0;
  /// Number of fragments produced.
  int fragment_count = 0;
  /// Number of fragments requested.
  int requested = 0;
  /// Number of points inside the input that were tested (<= options.partition_samples).
  int partition_samples = 0;
};

/// Computes the error figures of `fragments` against `input` (a closed outward mesh) and its mass
/// properties `input_mass` (volume in m^3). `requested` is the fragment count that was asked for.
/// Uses each fragment's `mass.volume` as given. Deterministic for a given options.seed.
FractureMetrics fracture_metrics(const Mesh& input, const MassProperties& input_mass,
                                 std::span<const Fragment> fragments, int requested,
                                 const FractureMetricsOptions& options = {});

}  // namespace shatter
