#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"

#include <limits>

namespace shatter {

bool SparseCholesky::analyze(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups) {
  impl_ = std::monostate{};
  NodeBlockCholesky blocks;
  const bool uniform = blocks.analyze(lower, groups);
  if (uniform && blocks.factor_flops() <= kNodeBlockMaxFlops) {
    impl_ = std::move(blocks);
    return true;
  }
  SupernodalCholesky supernodal;
  // The node order is the same AMD's; pass it on rather than ordering twice.
  const bool ok = uniform && !groups.empty() ? supernodal.analyze(lower, groups, blocks.node_order())
                                             : supernodal.analyze(lower, groups);
  if (!ok) return false;
  impl_ = std::move(supernodal);
  return true;
}

double SparseCholesky::factor_flops() const {
  if (const auto* b = std::get_if<NodeBlockCholesky>(&impl_)) return b->factor_flops();
  if (const auto* s = std::get_if<SupernodalCholesky>(&impl_)) return s->factor_flops();
  return 0.0;
}

std::size_t SparseCholesky::factor_bytes() const {
  if (const auto* b = std::get_if<NodeBlockCholesky>(&impl_)) return b->factor_bytes();
  if (const auto* s = std::get_if<SupernodalCholesky>(&impl_)) return s->factor_bytes();
  return 0;
}

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double>& lower) {
  if (auto* b = std::get_if<NodeBlockCholesky>(&impl_)) return b->factorize(lower);
  if (auto* s = std::get_if<SupernodalCholesky>(&impl_)) return s->factorize(lower);
  return false;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  if (const auto* f = std::get_if<NodeBlockCholesky>(&impl_)) return f->solve(b);
  if (const auto* s = std::get_if<SupernodalCholesky>(&impl_)) return s->solve(b);
  return Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
}

}  // namespace shatter
