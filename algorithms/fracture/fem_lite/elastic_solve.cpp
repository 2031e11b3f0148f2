#include "algorithms/fracture/fem_lite/elastic_solve.h"

#include "algorithms/core/node_block_cholesky.h"
#include "algorithms/fracture/fem_lite/hex_element.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shatter {

Result<FemSolution> solve_elastic(const HexGrid& grid, const Material& material, const FemLoads& loads) {
  const auto dofs = static_cast<Eigen::Index>(3 * grid.nodes.size());
  FemSolution solution;
  solution.displacements = Eigen::VectorXd::Zero(dofs);
  std::vector<char> fixed(static_cast<std::size_t>(dofs), 0);
  for (std::int32_t d : loads.fixed_dofs) fixed[static_cast<std::size_t>(d)] = 1;
  const auto fixed_count = static_cast<int>(std::count(fixed.begin(), fixed.end(), 1));
  const int free_dofs = static_cast<int>(dofs) - fixed_count;
  solution.report.free_dofs = free_dofs;
  if (free_dofs == 0) return solution;

  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs);
  for (Eigen::Index d = 0; d < dofs; ++d)
    if (!fixed[static_cast<std::size_t>(d)]) f[d] = loads.forces[d];
  const double f_norm = f.norm();
  if (f_norm == 0.0) return solution;

  // Every element is the same box: one element stiffness for all. Only the lower triangle is stored.
  // Every node keeps its three unknowns, so that the factorisation runs in 3 x 3 node blocks
  // (NodeBlockCholesky: fixed-size block arithmetic, about three times the speed of a scalar LDL^T on
  // these grids, and the same bits on every machine, unlike a BLAS-based one; docs/fem-lite.md). A
  // fixed unknown d keeps only its diagonal, s u_d = 0 with s the mean diagonal of the free unknowns:
  // nothing couples it to the others, so the factorisation leaves it apart exactly (u_d = 0) and the
  // free unknowns solve the system with the fixed ones eliminated.
  const Eigen::Matrix<double, 24, 24> ke = hex_stiffness(grid.cell, elasticity_matrix(material));
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(grid.elements.size() * 300 + static_cast<std::size_t>(fixed_count));
  double free_diagonal = 0.0;
  for (const auto& element : grid.elements) {
    for (int a = 0; a < 24; ++a) {
      const int row = 3 * element[a / 3] + a % 3;
      if (fixed[static_cast<std::size_t>(row)]) continue;
      free_diagonal += ke(a, a);
      for (int b = 0; b < 24; ++b) {
        const int col = 3 * element[b / 3] + b % 3;
        if (col <= row && !fixed[static_cast<std::size_t>(col)]) triplets.emplace_back(row, col, ke(a, b));
      }
    }
  }
  const double scale = free_diagonal / free_dofs;
  for (Eigen::Index d = 0; d < dofs; ++d)
    if (fixed[static_cast<std::size_t>(d)]) triplets.emplace_back(static_cast<int>(d), static_cast<int>(d), scale);
  Eigen::SparseMatrix<double> k(dofs, dofs);
  k.setFromTriplets(triplets.begin(), triplets.end());
  solution.report.nonzeros = static_cast<int>(k.nonZeros()) - fixed_count;  // those of the free unknowns

  std::vector<int> nodes(static_cast<std::size_t>(dofs));
  for (std::size_t d = 0; d < nodes.size(); ++d) nodes[d] = static_cast<int>(d / 3);
  NodeBlockCholesky cholesky;
  if (!cholesky.analyze(k, nodes) || !cholesky.factorize(k))
    return Error{"fem-lite: the stiffness matrix could not be factorised (the supports leave the piece free)"};
  solution.report.pivot_ratio = cholesky.pivot_ratio();
  if (!(solution.report.pivot_ratio > 1e-13))
    return Error{"fem-lite: the supports leave a rigid-body mode (fix at least three non-collinear nodes)"};
  Eigen::VectorXd u = cholesky.solve(f);
  for (Eigen::Index d = 0; d < dofs; ++d)
    if (fixed[static_cast<std::size_t>(d)]) u[d] = 0.0;  // 0 already; stated, not left to round-off
  const Eigen::VectorXd ku = k.selfadjointView<Eigen::Lower>() * u;
  solution.report.iterations = 1;
  solution.report.residual = (ku - f).norm() / f_norm;
  if (!u.allFinite() || !std::isfinite(solution.report.residual))
    return Error{"fem-lite: the elastic solve gave a non-finite displacement"};
  solution.displacements = u;
  return solution;
}

}  // namespace shatter
