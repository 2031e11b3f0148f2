#pragma once
/// K u and f - K u for the spring solves, skipping the columns whose u_j is zero, bit for bit what
/// Eigen's expressions give.
///
/// Design note: a planar structure under in-plane loads has its out-of-plane unknowns exactly zero
/// (half the columns of a wall's K), and a solve forms f - K u two or three times (once per refinement
/// step, and the reported residual when the last step was not stopped early). Eigen forms `k * u` column by column from +0, and `r = f - k * u` as r = f,
/// then r_i += K_ij (-u_j) column by column. A skipped term is a signed zero, and adding a signed zero
/// to a nonzero sum, or to +0, changes nothing, so the results agree bit for bit. The one exception
/// is a row of `sparse_residual` whose f_i is -0 and whose every term is zero: Eigen may end it at
/// +0, this at -0, an exactly zero residual either way.

#include <Eigen/SparseCore>

namespace shatter {

/// K u, as Eigen's `Eigen::VectorXd(k * u)` (`k` compressed, column-major).
Eigen::VectorXd sparse_product(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& u);

/// f - K u, as Eigen's `const Eigen::VectorXd r = f - k * u;` (`k` compressed, column-major).
Eigen::VectorXd sparse_residual(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                                const Eigen::VectorXd& u);

/// f - K u with every entry accumulated in long double (on x86-64 an 80-bit format with a 64-bit
/// significand; elsewhere the platform's, at least double), then rounded to double, and its norm taken
/// in long double: the residual of a u whose K u cancels f to within double's round-off of |K| |u| (a
/// structure near a mechanism), which the double `sparse_residual` cannot resolve.
struct ExtendedResidual {
  Eigen::VectorXd r;  ///< f - K u, each entry rounded to double
  double norm = 0.0;  ///< |f - K u|, 2-norm
};
ExtendedResidual extended_residual(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                                   const Eigen::VectorXd& u);

}  // namespace shatter
