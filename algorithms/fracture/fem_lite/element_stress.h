#pragma once
/// Stresses of the fem-lite elements at their centres, and the largest principal stress.

#include "algorithms/fracture/fem_lite/hex_grid.h"
#include "algorithms/core/material.h"

#include <Eigen/Core>

#include <vector>

namespace shatter {

/// The stress state at one element centre.
struct ElementStress {
  Eigen::Matrix<double, 6, 1> voigt = Eigen::Matrix<double, 6, 1>::Zero();  ///< (xx, yy, zz, xy, yz, zx), Pa
  double max_principal = 0.0;     ///< largest principal stress, Pa (positive in tension)
  /// Unit direction of max_principal, its largest component positive; zero when the stress is zero.
  Vec3 direction = Vec3::Zero();
};

/// Stress at the centre of each element of `grid` (#E) from the displacements (3 #N, m).
std::vector<ElementStress> element_stresses(const HexGrid& grid, const Material& material,
                                            const Eigen::VectorXd& displacements);

}  // namespace shatter
