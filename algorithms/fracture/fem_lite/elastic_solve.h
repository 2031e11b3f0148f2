#pragma once
/// The linear-elastic solve of fem-lite: assemble K over the grid, keep each fixed degree of freedom
/// apart (its own equation u = 0), solve K u = f with a sparse direct L L^T factorisation in 3 x 3
/// node blocks (NodeBlockCholesky, AMD ordering on the nodes).

#include "algorithms/core/result.h"
#include "algorithms/fracture/fem_lite/fem_loads.h"
#include "algorithms/fracture/fem_lite/hex_grid.h"
#include "algorithms/core/material.h"

#include <Eigen/Core>

namespace shatter {

/// Statistics of one solve.
struct FemSolveReport {
  int free_dofs = 0;           ///< unknowns of the reduced system
  int nonzeros = 0;            ///< stored entries of the reduced stiffness (lower triangle)
  int iterations = 0;          ///< 1 for the direct factorisation (0 when the load is zero)
  double residual = 0.0;       ///< |K u - f| / |f| on the reduced system (0 when f = 0)
  double pivot_ratio = 0.0;    ///< smallest / largest pivot L_ii^2 of the factor (a conditioning hint)
};

/// The displacements and the report.
struct FemSolution {
  Eigen::VectorXd displacements;   ///< 3 #N, m (0 at fixed degrees of freedom)
  FemSolveReport report;
};

/// Solves the grid under `loads`. Error when the restraints leave a rigid-body mode (a pivot vanishes)
/// or the result is not finite.
Result<FemSolution> solve_elastic(const HexGrid& grid, const Material& material, const FemLoads& loads);

}  // namespace shatter
