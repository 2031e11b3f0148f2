#pragma once
/// Error figures of the attributes a fracture carried (mesh_attributes.h): whether fragments render
/// like the input. Every attribute channel is linear over a triangle and a fracturer mixes corners at
/// the parameters of their positions, so at any point of a fragment's surface face the interpolated
/// values must equal the input's at the same point to round-off; these figures measure the distance.
///
/// Design note: the point's source triangle is the input triangle nearest it (TriangleLocator): a
/// surface face of a fragment lies inside one input triangle, so the nearest one is found at a
/// distance of round-off, also across UV seams (the point is inside the face, not on its edges).

#include "algorithms/core/mesh.h"
#include "algorithms/fracture/fracturer.h"

#include <cstdint>
#include <span>

namespace shatter {

/// Settings of attribute_metrics.
struct AttributeMetricsOptions {
  /// Random points on the fragments' surface faces (area-weighted over all fragments), >= 0.
  int samples = 1000;
  /// Seed of the sampling (SplitMix64); same seed, same figures.
  std::uint64_t seed = 2024;
};

/// Attribute errors of a set of fragments against the solid they came from.
struct AttributeMetrics {
  /// False when the input carries no attributes (every other figure is then 0).
  bool measured = false;
  /// Points sampled on surface faces.
  int samples = 0;
  /// Largest |UV on the fragment - UV of the input at the same point| over the samples and UV sets
  /// (UV units).
  double uv_error = 0.0;
  /// Largest |unit normal on the fragment - unit normal of the input at the same point| over the
  /// samples (both interpolated, then normalised).
  double normal_error = 0.0;
  /// Largest |unit corner normal - the cap's unit normal| over the corners of cut faces, where a cap is
  /// the cut faces of one fragment with one normal and its normal is their area-weighted geometric
  /// normal (the cut plane's, to round-off).
  double cap_normal_error = 0.0;
  /// Faces in the wrong material: a surface face whose material is not its source triangle's, or a
  /// cut face not in the interior material.
  int material_errors = 0;
};

/// Measures the attributes of `fragments` of `input`. Deterministic for a given seed.
AttributeMetrics attribute_metrics(const Mesh& input, std::span<const Fragment> fragments,
                                   const AttributeMetricsOptions& options = {});

}  // namespace shatter
