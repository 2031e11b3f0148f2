#include "algorithms/fracture/fem_lite/hex_element.h"

#include <cmath>

namespace shatter {

Eigen::Matrix<double, 6, 6> elasticity_matrix(const Material& material) {
  const double e = material.young_modulus;
  const double nu = material.poisson_ratio;
  const double lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu = e / (2.0 * (1.0 + nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  for (int a = 0; a < 3; ++a) {
    d(a, a) = lambda + 2.0 * mu;
    d(a + 3, a + 3) = mu;
  }
  return d;
}

Eigen::Matrix<double, 6, 24> strain_displacement(const Vec3& cell, const Vec3& local) {
  Eigen::Matrix<double, 6, 24> b = Eigen::Matrix<double, 6, 24>::Zero();
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner(2 * (c & 1) - 1, 2 * ((c >> 1) & 1) - 1, 2 * ((c >> 2) & 1) - 1);
    const Vec3 f = (Vec3::Ones() + corner.cwiseProduct(local)) / 2.0;  // the three 1D factors
    // dN/dx = dN/dxi * 2 / hx, with N = fx fy fz / ... and d fx / dxi = corner.x / 2.
    const double nx = corner.x() * f.y() * f.z() / cell.x();
    const double ny = corner.y() * f.x() * f.z() / cell.y();
    const double nz = corner.z() * f.x() * f.y() / cell.z();
    const int col = 3 * c;
    b(0, col) = nx;
    b(1, col + 1) = ny;
    b(2, col + 2) = nz;
    b(3, col) = ny;
    b(3, col + 1) = nx;
    b(4, col + 1) = nz;
    b(4, col + 2) = ny;
    b(5, col) = nz;
    b(5, col + 2) = nx;
  }
  return b;
}

Eigen::Matrix<double, 24, 24> hex_stiffness(const Vec3& cell, const Eigen::Matrix<double, 6, 6>& elasticity) {
  const double g = 1.0 / std::sqrt(3.0);
  const double det_j = cell.prod() / 8.0;  // weights are 1
  Eigen::Matrix<double, 24, 24> k = Eigen::Matrix<double, 24, 24>::Zero();
  for (int q = 0; q < 8; ++q) {
    const Vec3 local(g * (2 * (q & 1) - 1), g * (2 * ((q >> 1) & 1) - 1), g * (2 * ((q >> 2) & 1) - 1));
    const Eigen::Matrix<double, 6, 24> b = strain_displacement(cell, local);
    k.noalias() += b.transpose() * elasticity * b * det_j;
  }
  return k;
}

}  // namespace shatter
