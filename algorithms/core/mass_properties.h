#pragma once
/// Mass properties of a closed, outward-oriented triangle mesh of uniform density, by exact polyhedral
/// integrals (divergence theorem over the triangles; no sampling, no bounding boxes).

#include "algorithms/core/mesh.h"

#include <Eigen/Core>

namespace shatter {

/// Volume integrals of a solid. For a closed outward mesh `volume > 0`.
struct MassProperties {
  double volume = 0.0;                          ///< m^3 (signed: negative for an inward mesh)
  Vec3 centroid = Vec3::Zero();                 ///< m (zero when volume is zero)
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the centroid, per unit density, m^5
};

/// Volume, centroid and inertia tensor (about the centroid, for density 1) of a closed mesh.
MassProperties mass_properties(const Mesh& mesh);

/// Signed volume only, m^3 (cheaper than mass_properties).
double signed_volume(const Mesh& mesh);

/// Total area of the triangles carrying `tag`, m^2.
double tagged_area(const Mesh& mesh, FaceTag tag);

/// Total area of all triangles, m^2.
double surface_area(const Mesh& mesh);

}  // namespace shatter
