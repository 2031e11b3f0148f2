#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace shatter {

namespace {

/// True when entry (i, j) = v is kept: nonzero and above the round-off tolerance (compared squared, no
/// square root per entry; tolerance 0 keeps every nonzero even where v^2 underflows).
bool kept(const Eigen::VectorXd& diagonal, Eigen::Index i, Eigen::Index j, double v, double tolerance) {
  return v != 0.0 && (tolerance == 0.0 || v * v > tolerance * tolerance * std::abs(diagonal[i] * diagonal[j]));
}

}  // namespace

std::vector<std::vector<int>> decoupled_blocks(const Eigen::SparseMatrix<double>& k, double tolerance) {
  const int n = static_cast<int>(k.cols());
  const Eigen::VectorXd diagonal = k.diagonal();
  std::vector<int> component(static_cast<std::size_t>(n), -1), size;
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed) {
    if (component[static_cast<std::size_t>(seed)] >= 0) continue;
    const int id = static_cast<int>(size.size());
    size.push_back(0);
    component[static_cast<std::size_t>(seed)] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      ++size.back();
      for (Eigen::SparseMatrix<double>::InnerIterator it(k, c); it; ++it) {
        const int r = static_cast<int>(it.row());
        if (component[static_cast<std::size_t>(r)] < 0 && kept(diagonal, r, c, it.value(), tolerance)) {
          component[static_cast<std::size_t>(r)] = id;
          stack.push_back(r);
        }
      }
    }
  }
  // Each block's unknowns in ascending order, by one pass over the unknowns (no sort).
  std::vector<std::vector<int>> blocks(size.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) blocks[b].reserve(static_cast<std::size_t>(size[b]));
  for (int i = 0; i < n; ++i) blocks[static_cast<std::size_t>(component[static_cast<std::size_t>(i)])].push_back(i);
  return blocks;
}

Eigen::SparseMatrix<double> block_matrix(const Eigen::SparseMatrix<double>& k, std::span<const int> block,
                                         std::span<const int> position, double tolerance, bool lower_only) {
  assert(k.isCompressed());
  const Eigen::VectorXd diagonal = k.diagonal();
  const int m = static_cast<int>(block.size());
  // Straight into compressed columns: the block's columns are ascending and so are K's rows within a
  // column, so every column's rows come out sorted.
  std::vector<int> outer(static_cast<std::size_t>(m) + 1, 0), rows;
  std::vector<double> values;
  rows.reserve(static_cast<std::size_t>(k.nonZeros()));
  values.reserve(static_cast<std::size_t>(k.nonZeros()));
  const int* k_outer = k.outerIndexPtr();
  const int* k_inner = k.innerIndexPtr();
  const double* k_value = k.valuePtr();
  for (int c = 0; c < m; ++c) {
    const int gc = block[static_cast<std::size_t>(c)];
    for (int at = k_outer[gc]; at < k_outer[gc + 1]; ++at) {
      const int gr = k_inner[at];
      // The block's order is K's (both ascending), so the upper triangle is the rows above the
      // column's own: skipped before the tolerance's arithmetic.
      if (lower_only && gr < gc) continue;
      if (!kept(diagonal, gr, gc, k_value[at], tolerance) && gr != gc) continue;
      const int r = position[static_cast<std::size_t>(gr)];
      assert(!lower_only || r >= c);
      rows.push_back(r);
      values.push_back(k_value[at]);
    }
    outer[static_cast<std::size_t>(c) + 1] = static_cast<int>(rows.size());
  }
  Eigen::SparseMatrix<double> out(m, m);
  out.resizeNonZeros(static_cast<Eigen::Index>(rows.size()));
  std::copy(outer.begin(), outer.end(), out.outerIndexPtr());
  std::copy(rows.begin(), rows.end(), out.innerIndexPtr());
  std::copy(values.begin(), values.end(), out.valuePtr());
  return out;
}

std::vector<int> node_groups(std::span<const int> unknowns) {
  std::vector<int> groups(unknowns.size());
  for (std::size_t i = 0; i < unknowns.size(); ++i)
    groups[i] = i == 0 ? 0 : groups[i - 1] + (unknowns[i] / 6 != unknowns[i - 1] / 6 ? 1 : 0);
  return groups;
}

}  // namespace shatter
