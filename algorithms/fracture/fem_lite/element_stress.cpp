#include "algorithms/fracture/fem_lite/element_stress.h"

#include "algorithms/fracture/fem_lite/hex_element.h"

#include <Eigen/Eigenvalues>

namespace shatter {

std::vector<ElementStress> element_stresses(const HexGrid& grid, const Material& material,
                                            const Eigen::VectorXd& displacements) {
  // Every element is the same box: stress = (D B(0)) u_e with one 6 x 24 matrix.
  const Eigen::Matrix<double, 6, 24> db =
      elasticity_matrix(material) * strain_displacement(grid.cell, Vec3::Zero());
  std::vector<ElementStress> out(grid.elements.size());
  for (std::size_t e = 0; e < grid.elements.size(); ++e) {
    Eigen::Matrix<double, 24, 1> ue;
    for (int c = 0; c < 8; ++c) ue.segment<3>(3 * c) = displacements.segment<3>(3 * grid.elements[e][c]);
    ElementStress& s = out[e];
    s.voigt = db * ue;
    if (s.voigt.cwiseAbs().maxCoeff() == 0.0) continue;
    Eigen::Matrix3d tensor;
    tensor << s.voigt[0], s.voigt[3], s.voigt[5],  //
        s.voigt[3], s.voigt[1], s.voigt[4],        //
        s.voigt[5], s.voigt[4], s.voigt[2];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(tensor);
    s.max_principal = eigen.eigenvalues()[2];  // ascending
    Vec3 d = eigen.eigenvectors().col(2).normalized();
    Eigen::Index largest = 0;
    d.cwiseAbs().maxCoeff(&largest);
    if (d[largest] < 0) d = -d;
    s.direction = d;
  }
  return out;
}

}  // namespace shatter
