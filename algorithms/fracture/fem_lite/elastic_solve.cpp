#include "algorithms/fracture/fem_lite/elastic_solve.h"

#include "algorithms/fracture/fem_lite/hex_element.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shatter {

Result<FemSolution> solve_elastic(const HexGrid& grid, const Material& material, const FemLoads& loads) {
  const auto dofs = static_cast<Eigen::Index>(3 * grid.nodes.size());
  FemSolution solution;
  solution.displacements = Eigen::VectorXd::Zero(dofs);
  // Free degree of freedom -> unknown index, -1 when fixed.
  std::vector<int> unknown(static_cast<std::size_t>(dofs), 0);
  for (std::int32_t d : loads.fixed_dofs) unknown[d] = -1;
  int free_dofs = 0;
  for (int& u : unknown)
    if (u == 0) u = free_dofs++;
  solution.report.free_dofs = free_dofs;
  if (free_dofs == 0) return solution;

  Eigen::VectorXd f(free_dofs);
  for (Eigen::Index d = 0; d < dofs; ++d)
    if (unknown[d] >= 0) f[unknown[d]] = loads.forces[d];
  const double f_norm = f.norm();
  if (f_norm == 0.0) return solution;

  // Every element is the same box: one element stiffness for all. Only the lower triangle is stored.
  const Eigen::Matrix<double, 24, 24> ke = hex_stiffness(grid.cell, elasticity_matrix(material));
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(grid.elements.size() * 300);
  for (const auto& element : grid.elements) {
    for (int a = 0; a < 24; ++a) {
      const int row = unknown[3 * element[a / 3] + a % 3];
      if (row < 0) continue;
      for (int b = 0; b < 24; ++b) {
        const int col = unknown[3 * element[b / 3] + b % 3];
        if (col >= 0 && col <= row) triplets.emplace_back(row, col, ke(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> k(free_dofs, free_dofs);
  k.setFromTriplets(triplets.begin(), triplets.end());
  solution.report.nonzeros = static_cast<int>(k.nonZeros());

  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(k);
  if (ldlt.info() != Eigen::Success)
    return Error{"fem-lite: the stiffness matrix could not be factorised (the supports leave the piece free)"};
  const Eigen::VectorXd pivots = ldlt.vectorD().cwiseAbs();
  solution.report.pivot_ratio = pivots.minCoeff() / pivots.maxCoeff();
  if (!(solution.report.pivot_ratio > 1e-13))
    return Error{"fem-lite: the supports leave a rigid-body mode (fix at least three non-collinear nodes)"};
  const Eigen::VectorXd u = ldlt.solve(f);
  const Eigen::VectorXd ku = k.selfadjointView<Eigen::Lower>() * u;
  solution.report.iterations = 1;
  solution.report.residual = (ku - f).norm() / f_norm;
  if (!u.allFinite() || !std::isfinite(solution.report.residual))
    return Error{"fem-lite: the elastic solve gave a non-finite displacement"};
  for (Eigen::Index d = 0; d < dofs; ++d)
    if (unknown[d] >= 0) solution.displacements[d] = u[unknown[d]];
  return solution;
}

}  // namespace shatter
