#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shatter {

namespace {

/// True when entry (i, j) = v is kept: nonzero and above the round-off tolerance.
bool kept(const Eigen::VectorXd& diagonal, Eigen::Index i, Eigen::Index j, double v, double tolerance) {
  return v != 0.0 && std::abs(v) > tolerance * std::sqrt(std::abs(diagonal[i] * diagonal[j]));
}

}  // namespace

std::vector<std::vector<int>> decoupled_blocks(const Eigen::SparseMatrix<double>& k, double tolerance) {
  const int n = static_cast<int>(k.cols());
  const Eigen::VectorXd diagonal = k.diagonal();
  std::vector<int> component(static_cast<std::size_t>(n), -1);
  std::vector<std::vector<int>> blocks;
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed) {
    if (component[static_cast<std::size_t>(seed)] >= 0) continue;
    const int id = static_cast<int>(blocks.size());
    blocks.emplace_back();
    component[static_cast<std::size_t>(seed)] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      blocks.back().push_back(c);
      for (Eigen::SparseMatrix<double>::InnerIterator it(k, c); it; ++it) {
        const int r = static_cast<int>(it.row());
        if (component[static_cast<std::size_t>(r)] < 0 && kept(diagonal, r, c, it.value(), tolerance)) {
          component[static_cast<std::size_t>(r)] = id;
          stack.push_back(r);
        }
      }
    }
    std::sort(blocks.back().begin(), blocks.back().end());
  }
  return blocks;
}

Eigen::SparseMatrix<double> block_matrix(const Eigen::SparseMatrix<double>& k, std::span<const int> block,
                                         std::span<const int> position, double tolerance, bool lower_only) {
  const Eigen::VectorXd diagonal = k.diagonal();
  const Eigen::Index m = static_cast<Eigen::Index>(block.size());
  Eigen::SparseMatrix<double> out(m, m);
  Eigen::VectorXi counts = Eigen::VectorXi::Zero(m);
  for (Eigen::Index c = 0; c < m; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, block[static_cast<std::size_t>(c)]); it; ++it)
      ++counts[c];
  out.reserve(counts);
  // The block's columns are ascending and so are K's rows within a column: insertion stays sorted.
  for (Eigen::Index c = 0; c < m; ++c) {
    const int gc = block[static_cast<std::size_t>(c)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, gc); it; ++it) {
      const int gr = static_cast<int>(it.row());
      if (!kept(diagonal, gr, gc, it.value(), tolerance) && gr != gc) continue;
      const int r = position[static_cast<std::size_t>(gr)];
      if (lower_only && r < c) continue;
      out.insert(r, c) = it.value();
    }
  }
  out.makeCompressed();
  return out;
}

std::vector<int> node_groups(std::span<const int> unknowns) {
  std::vector<int> groups(unknowns.size());
  for (std::size_t i = 0; i < unknowns.size(); ++i)
    groups[i] = i == 0 ? 0 : groups[i - 1] + (unknowns[i] / 6 != unknowns[i - 1] / 6 ? 1 : 0);
  return groups;
}

}  // namespace shatter
