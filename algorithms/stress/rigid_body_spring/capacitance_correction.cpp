#include "algorithms/stress/rigid_body_spring/capacitance_correction.h"

#include <cassert>

namespace shatter {

void CapacitanceCorrection::reset(std::span<const double> base) {
  base_.assign(base.begin(), base.end());
  has_base_ = true;
  nodes_.clear();
  std::fill(slot_.begin(), slot_.end(), -1);
  paths_.clear();
  columns_.clear();
  g_.resize(0, 0);
  e_.resize(0, 0);
  has_z_ = false;
}

void CapacitanceCorrection::clear() {
  reset({});
  has_base_ = false;
}

bool CapacitanceCorrection::update(const NodeBlockCholesky& factor, const Eigen::SparseMatrix<double>& lower,
                                   double max_flops) {
  assert(has_base_ && base_.size() == static_cast<std::size_t>(lower.nonZeros()));
  const int g = factor.node_size();
  const int n = static_cast<int>(lower.cols());
  if (g == 0 || n % g != 0) return false;
  if (size_ != g || slot_.size() != static_cast<std::size_t>(n / g)) {
    size_ = g;
    slot_.assign(static_cast<std::size_t>(n / g), -1);
    nodes_.clear();
  }
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  const double* value = lower.valuePtr();
  // The nodes with a changed entry, in the order of their columns; the ones already in P keep theirs.
  const std::size_t known = nodes_.size();
  const auto add = [&](int node) {
    if (slot_[static_cast<std::size_t>(node)] >= 0) return;
    slot_[static_cast<std::size_t>(node)] = static_cast<int>(nodes_.size());
    nodes_.push_back(node);
  };
  for (int c = 0; c < n; ++c)
    for (int at = outer[c]; at < outer[c + 1]; ++at)
      if (value[at] != base_[static_cast<std::size_t>(at)]) add(c / g), add(inner[at] / g);
  const int m = static_cast<int>(nodes_.size()) * g;
  // What this update would cost: the new nodes' columns (a g x g product per block of L on their
  // paths), G's new blocks (at most a path's length each), and the capacitance's LU.
  const double product = 2.0 * g * g * g;
  double flops = 2.0 / 3.0 * static_cast<double>(m) * m * m;
  for (std::size_t i = known; i < nodes_.size(); ++i) {
    int length = 0;
    flops += product * (factor.path_blocks(nodes_[i], length) + static_cast<double>(length) * static_cast<double>(nodes_.size()));
  }
  last_flops_ = flops;
  if (m > kMaxUnknowns || flops > max_flops) {
    // Dearer than the refactorisation it would spare: forget the new ones (the caller refactorises).
    for (std::size_t i = known; i < nodes_.size(); ++i) slot_[static_cast<std::size_t>(nodes_[i])] = -1;
    nodes_.resize(known);
    return false;
  }

  // The new nodes' columns of L^-1 P, and G's new rows and columns: G_ab = (L^-1 P_a)^T (L^-1 P_b),
  // summed over the part the two paths share (from their lowest common ancestor up).
  paths_.resize(nodes_.size());
  columns_.resize(nodes_.size());
  for (std::size_t i = known; i < nodes_.size(); ++i) factor.inverse_factor_columns(nodes_[i], paths_[i], columns_[i]);
  g_.conservativeResize(m, m);
  const int gg = g * g;
  for (std::size_t a = known; a < nodes_.size(); ++a)
    for (std::size_t b = 0; b <= a; ++b) {
      double block[NodeBlockCholesky::kMaxNodeSize * NodeBlockCholesky::kMaxNodeSize] = {};
      const std::vector<int>& pa = paths_[a];
      const std::vector<int>& pb = paths_[b];
      // Both paths run up to their root, so what they share is the end of each, from the lowest
      // common ancestor on.
      for (std::size_t i = pa.size(), j = pb.size(); i > 0 && j > 0 && pa[i - 1] == pb[j - 1]; --i, --j) {
        const double* ya = columns_[a].data() + (i - 1) * static_cast<std::size_t>(gg);
        const double* yb = columns_[b].data() + (j - 1) * static_cast<std::size_t>(gg);
        for (int q = 0; q < g; ++q)      // column q of yb
          for (int p = 0; p < g; ++p) {  // column p of ya
            double sum = 0.0;
            for (int t = 0; t < g; ++t) sum += ya[p * g + t] * yb[q * g + t];
            block[q * g + p] += sum;
          }
      }
      const Eigen::Index ra = static_cast<Eigen::Index>(a) * g, rb = static_cast<Eigen::Index>(b) * g;
      for (int q = 0; q < g; ++q)
        for (int p = 0; p < g; ++p) {
          g_(ra + p, rb + q) = block[q * g + p];
          g_(rb + q, ra + p) = block[q * g + p];
        }
    }

  // E over the nodes in P (an entry that changed has both its nodes there; a few blocks per node, so
  // sparse), then I - G E.
  std::vector<Eigen::Triplet<double>> entries;
  for (const int node : nodes_)
    for (int t = 0; t < g; ++t) {
      const int c = node * g + t;
      const int ic = slot_[static_cast<std::size_t>(node)] * g + t;
      for (int at = outer[c]; at < outer[c + 1]; ++at) {
        const int r = inner[at];
        const int slot = slot_[static_cast<std::size_t>(r / g)];
        const double d = base_[static_cast<std::size_t>(at)] - value[at];
        if (slot < 0 || d == 0.0) continue;
        const int ir = slot * g + r % g;
        entries.emplace_back(ir, ic, d);
        if (ir != ic) entries.emplace_back(ic, ir, d);
      }
    }
  e_.resize(m, m);
  e_.setFromTriplets(entries.begin(), entries.end());
  if (m == 0) return true;
  Eigen::MatrixXd capacitance = -(g_ * e_);
  capacitance.diagonal().array() += 1.0;
  capacitance_.compute(capacitance);
  return capacitance_.rcond() >= 1e-12;
}

Eigen::VectorXd CapacitanceCorrection::solve(const NodeBlockCholesky& factor, const Eigen::VectorXd& b) const {
  // z = K_B^-1 b, kept for the next solve of the same b (a cascade's rounds all start from the loads).
  if (!has_z_ || b.size() != z_rhs_.size() || b != z_rhs_) {
    z_ = factor.solve(b);
    z_rhs_ = b;
    has_z_ = true;
  }
  if (nodes_.empty()) return z_;
  const int g = size_;
  const Eigen::Index m = g_.rows();
  Eigen::VectorXd z_p(m);
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (int t = 0; t < g; ++t) z_p[static_cast<Eigen::Index>(i) * g + t] = z_[nodes_[i] * g + t];
  const Eigen::VectorXd w = e_ * capacitance_.solve(z_p);
  // K_B^-1 P w = L^-T (L^-1 P) w: the columns of L^-1 P on their paths, then one triangular solve.
  Eigen::VectorXd y = Eigen::VectorXd::Zero(b.size());
  const int gg = g * g;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const double* wi = w.data() + static_cast<Eigen::Index>(i) * g;
    for (std::size_t at = 0; at < paths_[i].size(); ++at) {
      const double* block = columns_[i].data() + at * static_cast<std::size_t>(gg);
      double* yk = y.data() + static_cast<std::ptrdiff_t>(paths_[i][at]) * g;
      for (int q = 0; q < g; ++q)
        for (int p = 0; p < g; ++p) yk[p] += block[q * g + p] * wi[q];
    }
  }
  return z_ + factor.solve_transposed_factor(y);
}

}  // namespace shatter
