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

/// The volume and centroid of a closed mesh (no second moments).
struct VolumeCentroid {
  double volume = 0.0;           ///< m^3, signed as MassProperties::volume
  Vec3 centroid = Vec3::Zero();  ///< m (zero when volume is zero)
};

/// mass_properties' volume and centroid without its second moments (about 40 % of its cost): the same
/// sums in the same order, so the same values bit for bit. For a piece that is only cut again.
VolumeCentroid volume_centroid(const Mesh& mesh);

/// Signed volume only, m^3 (cheaper than mass_properties).
double signed_volume(const Mesh& mesh);

/// Total area of the triangles carrying `tag`, m^2.
double tagged_area(const Mesh& mesh, FaceTag tag);

/// Total area of all triangles, m^2.
double surface_area(const Mesh& mesh);

}  // namespace shatter
