#include "algorithms/stress/rigid_body_spring/sparse_product.h"

#include <cassert>
#include <cmath>
#include <vector>

namespace shatter {
namespace {

/// out_i += K_ij * scale * u_j over the columns j with u_j != 0, in column order.
void add_columns(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& u, double scale, Eigen::VectorXd& out) {
  assert(k.isCompressed() && k.cols() == u.size() && k.rows() == out.size());
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  const double* value = k.valuePtr();
  double* o = out.data();
  for (Eigen::Index j = 0; j < k.cols(); ++j) {
    if (u[j] == 0.0) continue;
    const double uj = scale * u[j];
    for (int at = outer[j]; at < outer[j + 1]; ++at) o[inner[at]] += value[at] * uj;
  }
}

}  // namespace

Eigen::VectorXd sparse_product(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& u) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(k.rows());
  add_columns(k, u, 1.0, out);
  return out;
}

Eigen::VectorXd sparse_residual(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                                const Eigen::VectorXd& u) {
  Eigen::VectorXd out = f;
  add_columns(k, u, -1.0, out);
  return out;
}

ExtendedResidual extended_residual(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                                   const Eigen::VectorXd& u) {
  assert(k.isCompressed() && k.cols() == u.size() && k.rows() == f.size());
  std::vector<long double> r(f.data(), f.data() + f.size());
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  const double* value = k.valuePtr();
  for (Eigen::Index j = 0; j < k.cols(); ++j) {
    const long double uj = u[j];
    for (int at = outer[j]; at < outer[j + 1]; ++at) r[static_cast<std::size_t>(inner[at])] -= value[at] * uj;
  }
  ExtendedResidual out;
  out.r.resize(f.size());
  long double squares = 0.0L;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    const long double ri = r[static_cast<std::size_t>(i)];
    out.r[i] = static_cast<double>(ri);
    squares += ri * ri;
  }
  out.norm = static_cast<double>(std::sqrt(squares));
  return out;
}

}  // namespace shatter
