#pragma once
/// The 8-node trilinear brick element of fem-lite, for an axis-aligned box cell of isotropic material.
///
/// Conventions: corner c = i + 2 j + 4 k sits at local coordinates (2i-1, 2j-1, 2k-1); displacement
/// degrees of freedom are ordered (ux, uy, uz) per corner, 24 in all; stresses and strains in Voigt
/// order (xx, yy, zz, xy, yz, zx) with engineering shear strains.

#include "algorithms/core/mesh.h"
#include "algorithms/core/material.h"

#include <Eigen/Core>

namespace shatter {

/// Isotropic elasticity matrix (6 x 6, Pa): stress = D strain.
Eigen::Matrix<double, 6, 6> elasticity_matrix(const Material& material);

/// Strain-displacement matrix (6 x 24, 1/m) of a box cell of size `cell` (m) at local coordinates
/// `local` in [-1, 1]^3.
Eigen::Matrix<double, 6, 24> strain_displacement(const Vec3& cell, const Vec3& local);

/// Element stiffness (24 x 24, N/m) of a box cell of size `cell` (m), by 2 x 2 x 2 Gauss quadrature
/// (exact for the trilinear brick on a box).
Eigen::Matrix<double, 24, 24> hex_stiffness(const Vec3& cell, const Eigen::Matrix<double, 6, 6>& elasticity);

}  // namespace shatter
