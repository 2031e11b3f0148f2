#include "algorithms/core/node_block_cholesky.h"

#include "algorithms/core/node_ordering.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>

namespace shatter {

bool NodeBlockCholesky::analyze(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups) {
  *this = NodeBlockCholesky{};
  assert(lower.isCompressed() && lower.rows() == lower.cols());
  const int n = static_cast<int>(lower.cols());
  std::vector<int> own_groups;
  if (groups.empty()) {
    own_groups.resize(static_cast<std::size_t>(n));
    for (int c = 0; c < n; ++c) own_groups[static_cast<std::size_t>(c)] = c;
    groups = own_groups;
  }
  assert(static_cast<int>(groups.size()) == n);
  const int node_count = n > 0 ? groups[static_cast<std::size_t>(n - 1)] + 1 : 0;
  if (node_count == 0 || n % node_count != 0) return false;
  const int g = n / node_count;
  if (g > kMaxNodeSize) return false;
  for (int c = 0; c < n; ++c)  // node v owns columns g v .. g v + g - 1
    if (groups[static_cast<std::size_t>(c)] != c / g) return false;
  std::optional<std::vector<int>> order = node_amd_order(lower, groups);
  if (!order) return false;
  size_ = g;
  nodes_ = node_count;
  value_count_ = static_cast<std::size_t>(lower.nonZeros());
  order_ = std::move(*order);
  position_.resize(static_cast<std::size_t>(nodes_));
  for (int k = 0; k < nodes_; ++k) position_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])] = k;
  const std::vector<int>& position = position_;

  // K's blocks by row of the elimination order: block (k, i) = (later, earlier) position of a node pair
  // with entries in lower. Lower holds each pair once (in the columns of its earlier node in the
  // original numbering), so one pass finds each pair once; rows are then filled by counting, each
  // row's diagonal block last (present even where K stores nothing of it: then singular).
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  std::vector<int> mark(static_cast<std::size_t>(nodes_), -1);
  std::vector<int>& pairs = pairs_;  // (node v, node w > v), by v
  row_start_.assign(static_cast<std::size_t>(nodes_) + 1, 0);
  for (int v = 0; v < nodes_; ++v) {
    mark[static_cast<std::size_t>(v)] = v;
    for (int at = outer[g * v]; at < outer[g * v + g]; ++at) {
      const int w = inner[at] / g;
      if (w < v) {  // not a lower triangle
        *this = NodeBlockCholesky{};
        return false;
      }
      if (mark[static_cast<std::size_t>(w)] == v) continue;
      mark[static_cast<std::size_t>(w)] = v;
      pairs.push_back(v);
      pairs.push_back(w);
      const int pv = position[static_cast<std::size_t>(v)], pw = position[static_cast<std::size_t>(w)];
      ++row_start_[static_cast<std::size_t>(std::max(pv, pw)) + 1];
    }
  }
  for (int k = 0; k < nodes_; ++k)
    row_start_[static_cast<std::size_t>(k) + 1] += row_start_[static_cast<std::size_t>(k)] + 1;  // + the diagonal
  row_column_.assign(static_cast<std::size_t>(row_start_.back()), 0);
  std::vector<int> next(row_start_.begin(), row_start_.end() - 1);
  std::vector<int>& pair_block = pair_block_;
  pair_block.resize(pairs.size() / 2);
  for (std::size_t p = 0; p < pairs.size(); p += 2) {
    const int pv = position[static_cast<std::size_t>(pairs[p])], pw = position[static_cast<std::size_t>(pairs[p + 1])];
    const int block = next[static_cast<std::size_t>(std::max(pv, pw))]++;
    row_column_[static_cast<std::size_t>(block)] = std::min(pv, pw);
    pair_block[p / 2] = block;
  }
  for (int k = 0; k < nodes_; ++k) {
    const int diagonal = row_start_[static_cast<std::size_t>(k) + 1] - 1;
    row_column_[static_cast<std::size_t>(diagonal)] = k;
  }
  // Elimination tree and column counts of L below the diagonal, in blocks (Liu's algorithm with the
  // row-by-row walk that Eigen's SimplicialCholesky uses).
  parent_.assign(static_cast<std::size_t>(nodes_), -1);
  std::vector<int> flag(static_cast<std::size_t>(nodes_), -1), column_count(static_cast<std::size_t>(nodes_), 0);
  for (int k = 0; k < nodes_; ++k) {
    flag[static_cast<std::size_t>(k)] = k;
    for (int at = row_start_[static_cast<std::size_t>(k)]; at < row_start_[static_cast<std::size_t>(k) + 1]; ++at)
      for (int j = row_column_[static_cast<std::size_t>(at)]; flag[static_cast<std::size_t>(j)] != k;
           j = parent_[static_cast<std::size_t>(j)]) {
        if (parent_[static_cast<std::size_t>(j)] == -1) parent_[static_cast<std::size_t>(j)] = k;
        ++column_count[static_cast<std::size_t>(j)];
        flag[static_cast<std::size_t>(j)] = k;
      }
  }
  column_start_.assign(static_cast<std::size_t>(nodes_) + 1, 0);
  for (int j = 0; j < nodes_; ++j) {
    const int c = column_count[static_cast<std::size_t>(j)];
    column_start_[static_cast<std::size_t>(j) + 1] = column_start_[static_cast<std::size_t>(j)] + c;
    for (int t = 0; t < g; ++t) {  // scalar column t of the node: c g below, g - t in the diagonal block
      const double entries = static_cast<double>(c) * g + (g - t);
      flops_ += entries * entries;
    }
  }
  return true;
}

void NodeBlockCholesky::build_gather(const Eigen::SparseMatrix<double>& lower) {
  // Each scalar entry's place in its block: the pass over lower again, with the block of each pair at
  // hand. Done by the first factorisation, so that an analysis only asked for its flop count (a system
  // that goes to CHOLMOD) does not pay for it.
  const int g = size_;
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  const std::vector<int>& position = position_;
  const std::vector<int>& pairs = pairs_;
  const std::vector<int>& pair_block = pair_block_;
  const int gg = g * g;
  gather_.assign(static_cast<std::size_t>(row_start_.back()) * static_cast<std::size_t>(gg), -1);
  std::vector<int> block_of(static_cast<std::size_t>(nodes_), -1);
  std::size_t p = 0;
  for (int v = 0; v < nodes_; ++v) {
    const int pv = position[static_cast<std::size_t>(v)];
    block_of[static_cast<std::size_t>(v)] = row_start_[static_cast<std::size_t>(pv) + 1] - 1;
    for (; p < pairs.size() && pairs[p] == v; p += 2)
      block_of[static_cast<std::size_t>(pairs[p + 1])] = pair_block[p / 2];
    for (int c = g * v; c < g * v + g; ++c)
      for (int at = outer[c]; at < outer[c + 1]; ++at) {
        const int r = inner[at], w = r / g;
        // Block (k, i) with k the later position: local row in k's unknowns, local column in i's.
        const bool row_later = position[static_cast<std::size_t>(w)] >= pv;
        const int local_row = row_later ? r % g : c % g, local_column = row_later ? c % g : r % g;
        gather_[static_cast<std::size_t>(block_of[static_cast<std::size_t>(w)]) * static_cast<std::size_t>(gg) +
                static_cast<std::size_t>(local_column * g + local_row)] = at;
      }
  }
  pairs_ = {};  // not needed again
  pair_block_ = {};
}

void NodeBlockCholesky::build_rows() {
  // The rows of each column of L, ascending: row k enters the columns of its reach in the elimination
  // tree (the symbolic part of the up-looking factorisation), so that any row can be recomputed alone.
  std::vector<int> fill(column_start_.begin(), column_start_.end() - 1);
  std::fill(flag_.begin(), flag_.end(), -1);
  for (int k = 0; k < nodes_; ++k) {
    flag_[static_cast<std::size_t>(k)] = k;
    const int last = row_start_[static_cast<std::size_t>(k) + 1] - 1;
    for (int at = row_start_[static_cast<std::size_t>(k)]; at < last; ++at)
      for (int j = row_column_[static_cast<std::size_t>(at)]; flag_[static_cast<std::size_t>(j)] != k;
           j = parent_[static_cast<std::size_t>(j)]) {
        rows_[static_cast<std::size_t>(fill[static_cast<std::size_t>(j)]++)] = k;
        flag_[static_cast<std::size_t>(j)] = k;
      }
  }
}

void NodeBlockCholesky::mark_changed_rows(const Eigen::SparseMatrix<double>& lower) {
  const int g = size_;
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  const double* values = lower.valuePtr();
  double* last = last_values_.data();
  std::fill(stale_.begin(), stale_.end(), std::uint8_t{0});
  for (int c = 0; c < static_cast<int>(lower.cols()); ++c)
    for (int at = outer[c]; at < outer[c + 1]; ++at)
      // Bit by bit (a zero's sign or a NaN payload is a change): the kept rows must be exactly those
      // a factorisation from scratch would compute.
      if (std::memcmp(values + at, last + at, sizeof(double)) != 0) {
        // The entry is K(k, i) for the later k of its two nodes' positions: row k reads it.
        const int pc = position_[static_cast<std::size_t>(c / g)];
        const int pr = position_[static_cast<std::size_t>(inner[at] / g)];
        stale_[static_cast<std::size_t>(std::max(pc, pr))] = 1;
        last[at] = values[at];  // the new values become the last ones (cleared if this one fails)
      }
  // Row k reads the rows j of its pattern (L(k, j) != 0), all of them its descendants, and the parent
  // of j reads j (it is the first row of column j): the rows to recompute are the changed ones and
  // their ancestors. Parents come later, so one ascending pass closes the set.
  for (int k = 0; k < nodes_; ++k)
    if (stale_[static_cast<std::size_t>(k)] && parent_[static_cast<std::size_t>(k)] >= 0)
      stale_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(k)])] = 1;
}

std::size_t NodeBlockCholesky::factor_bytes() const {
  const std::size_t gg = static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_);
  const std::size_t blocks = column_start_.empty() ? 0 : static_cast<std::size_t>(column_start_.back());
  const std::size_t nodes = static_cast<std::size_t>(nodes_);
  const std::size_t gathered = row_start_.empty() ? 0 : static_cast<std::size_t>(row_start_.back()) * gg;
  // Doubles: L's blocks, the diagonal inverses and the workspace, the last factorised values. Ints:
  // L's rows, the gather map, K's block columns and eight per node (order, position, tree, starts,
  // workspace); a byte per node marks the rows to recompute.
  return (blocks * gg + 2 * nodes * gg + value_count_) * sizeof(double) +
         (blocks + gathered + row_column_.size() + 8 * nodes) * sizeof(int) + nodes;
}

namespace {

/// The inverse of a lower-triangular block with a positive diagonal, by forward substitution (unrolled
/// for the fixed size; Eigen's triangular solves of fixed-size blocks take its general blocked path).
template <int G>
Eigen::Matrix<double, G, G> lower_inverse(const Eigen::Matrix<double, G, G>& l) {
  Eigen::Matrix<double, G, G> inverse = Eigen::Matrix<double, G, G>::Zero();
  for (int c = 0; c < G; ++c)
    for (int r = c; r < G; ++r) {
      double s = r == c ? 1.0 : 0.0;
      for (int k = c; k < r; ++k) s -= l(r, k) * inverse(k, c);
      inverse(r, c) = s / l(r, r);
    }
  return inverse;
}

}  // namespace

template <int G>
bool NodeBlockCholesky::factorize_blocks(const double* values, bool all_rows) {
  using Block = Eigen::Matrix<double, G, G>;
  using BlockMap = Eigen::Map<Block>;
  constexpr int kEntries = G * G;
  std::fill(flag_.begin(), flag_.end(), -1);
  rows_refactorised_ = 0;
  const auto gathered = [&](int at) {
    Block b;
    const int* from = gather_.data() + static_cast<std::size_t>(at) * kEntries;
    for (int e = 0; e < kEntries; ++e) b.data()[e] = from[e] >= 0 ? values[from[e]] : 0.0;
    return b;
  };
  for (int k = 0; k < nodes_; ++k) {
    if (!all_rows && !stale_[static_cast<std::size_t>(k)]) continue;
    ++rows_refactorised_;
    // Scatter row k of K into the workspace and collect the reach of row k in the elimination tree,
    // in topological order (pattern_[top .. N - 1]).
    int top = nodes_;
    flag_[static_cast<std::size_t>(k)] = k;
    const int last = row_start_[static_cast<std::size_t>(k) + 1] - 1;  // the diagonal block
    for (int at = row_start_[static_cast<std::size_t>(k)]; at < last; ++at) {
      int i = row_column_[static_cast<std::size_t>(at)];
      BlockMap(work_.data() + static_cast<std::size_t>(i) * kEntries) = gathered(at);
      int length = 0;
      for (; flag_[static_cast<std::size_t>(i)] != k; i = parent_[static_cast<std::size_t>(i)]) {
        stack_[static_cast<std::size_t>(length++)] = i;
        flag_[static_cast<std::size_t>(i)] = k;
      }
      while (length > 0) pattern_[static_cast<std::size_t>(--top)] = stack_[static_cast<std::size_t>(--length)];
    }
    Block d = gathered(last);
    for (; top < nodes_; ++top) {
      const int j = pattern_[static_cast<std::size_t>(top)];
      BlockMap x(work_.data() + static_cast<std::size_t>(j) * kEntries);
      // L(k, j) = X L(j, j)^-T, then X(i) -= L(k, j) L(i, j)^T for the rows i < k of column j (the
      // column's rows are ascending, and k is among them).
      const Eigen::Map<const Block> inverse_jj(diagonal_.data() + static_cast<std::size_t>(j) * kEntries);
      const Block l_kj = (x * inverse_jj.transpose()).eval();
      x.setZero();
      int q = column_start_[static_cast<std::size_t>(j)];
      for (; rows_[static_cast<std::size_t>(q)] != k; ++q) {
        const Eigen::Map<const Block> l_ij(blocks_.data() + static_cast<std::size_t>(q) * kEntries);
        BlockMap(work_.data() + static_cast<std::size_t>(rows_[static_cast<std::size_t>(q)]) * kEntries).noalias() -=
            l_kj * l_ij.transpose();
      }
      d.noalias() -= l_kj * l_kj.transpose();
      BlockMap(blocks_.data() + static_cast<std::size_t>(q) * kEntries) = l_kj;
    }
    const Eigen::LLT<Block, Eigen::Lower> llt(d);
    if (llt.info() != Eigen::Success) return false;
    const Block l_kk = llt.matrixL();
    if (!l_kk.allFinite() || (l_kk.diagonal().array() <= 0.0).any()) return false;
    const Block inverse = lower_inverse<G>(l_kk);
    if (!inverse.allFinite()) return false;
    BlockMap(diagonal_.data() + static_cast<std::size_t>(k) * kEntries) = inverse;
  }
  return true;
}

bool NodeBlockCholesky::factorize(const Eigen::SparseMatrix<double>& lower) {
  const bool after_success = factorised_;
  factorised_ = false;
  if (nodes_ == 0 || !analysed()) return false;
  assert(lower.cols() == static_cast<Eigen::Index>(nodes_) * size_);
  if (work_.empty()) {  // the factor's storage, on the first factorisation (an analysis may go unused)
    build_gather(lower);
    const std::size_t gg = static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_);
    const std::size_t nodes = static_cast<std::size_t>(nodes_);
    rows_.resize(static_cast<std::size_t>(column_start_.back()));
    blocks_.resize(rows_.size() * gg);
    diagonal_.resize(nodes * gg);
    work_.assign(nodes * gg, 0.0);
    flag_.resize(nodes);
    stack_.resize(nodes);
    pattern_.resize(nodes);
    stale_.resize(nodes);
    build_rows();
  }
  const std::size_t entries = static_cast<std::size_t>(lower.nonZeros());
  const bool all_rows = !after_success || last_values_.size() != entries;
  if (!all_rows) mark_changed_rows(lower);
  bool ok = false;
  switch (size_) {
    case 1: ok = factorize_blocks<1>(lower.valuePtr(), all_rows); break;
    case 2: ok = factorize_blocks<2>(lower.valuePtr(), all_rows); break;
    case 3: ok = factorize_blocks<3>(lower.valuePtr(), all_rows); break;
    case 4: ok = factorize_blocks<4>(lower.valuePtr(), all_rows); break;
    case 5: ok = factorize_blocks<5>(lower.valuePtr(), all_rows); break;
    case 6: ok = factorize_blocks<6>(lower.valuePtr(), all_rows); break;
    default: break;
  }
  // A failure comes after the failing row's reach was used and zeroed, so the workspace is clean.
  assert(std::all_of(work_.begin(), work_.end(), [](double x) { return x == 0.0; }));
  factorised_ = ok;
  if (!ok)
    last_values_.clear();
  else if (all_rows)  // a partial one updated the changed values as it found them
    last_values_.assign(lower.valuePtr(), lower.valuePtr() + entries);
  return ok;
}

template <int G>
void NodeBlockCholesky::solve_blocks(double* x, bool forward) const {
  using Vec = Eigen::Matrix<double, G, 1>;
  using Block = Eigen::Matrix<double, G, G>;
  constexpr int kEntries = G * G;
  const auto segment = [&](int j) { return Eigen::Map<Vec>(x + static_cast<std::size_t>(j) * G); };
  for (int j = 0; forward && j < nodes_; ++j) {  // L y = b
    const Eigen::Map<const Block> inverse_jj(diagonal_.data() + static_cast<std::size_t>(j) * kEntries);
    const Vec y = inverse_jj * segment(j);
    segment(j) = y;
    for (int q = column_start_[static_cast<std::size_t>(j)]; q < column_start_[static_cast<std::size_t>(j) + 1]; ++q)
      segment(rows_[static_cast<std::size_t>(q)]).noalias() -=
          Eigen::Map<const Block>(blocks_.data() + static_cast<std::size_t>(q) * kEntries) * y;
  }
  for (int j = nodes_ - 1; j >= 0; --j) {  // L^T x = y
    Vec s = segment(j);
    for (int q = column_start_[static_cast<std::size_t>(j)]; q < column_start_[static_cast<std::size_t>(j) + 1]; ++q)
      s.noalias() -= Eigen::Map<const Block>(blocks_.data() + static_cast<std::size_t>(q) * kEntries).transpose() *
                     segment(rows_[static_cast<std::size_t>(q)]);
    const Eigen::Map<const Block> inverse_jj(diagonal_.data() + static_cast<std::size_t>(j) * kEntries);
    segment(j) = inverse_jj.transpose() * s;
  }
}

template <int G>
void NodeBlockCholesky::path_columns(int node, std::vector<int>& path, std::vector<double>& columns) const {
  using Block = Eigen::Matrix<double, G, G>;
  constexpr int kEntries = G * G;
  for (int j = position_[static_cast<std::size_t>(node)]; j >= 0; j = parent_[static_cast<std::size_t>(j)]) path.push_back(j);
  columns.assign(path.size() * kEntries, 0.0);
  const auto at = [&](std::size_t i) { return Eigen::Map<Block>(columns.data() + i * kEntries); };
  at(0).setIdentity();
  // Column-oriented forward solve L Y = P over the path: column j of L has its rows among j's ancestors,
  // all on the path, and both lists ascend, so one merge finds them.
  for (std::size_t i = 0; i < path.size(); ++i) {
    const int j = path[i];
    const Eigen::Map<const Block> inverse_jj(diagonal_.data() + static_cast<std::size_t>(j) * kEntries);
    const Block y = (inverse_jj * at(i)).eval();
    at(i) = y;
    std::size_t t = i + 1;
    for (int q = column_start_[static_cast<std::size_t>(j)]; q < column_start_[static_cast<std::size_t>(j) + 1]; ++q) {
      while (path[t] != rows_[static_cast<std::size_t>(q)]) ++t;
      at(t).noalias() -= Eigen::Map<const Block>(blocks_.data() + static_cast<std::size_t>(q) * kEntries) * y;
    }
  }
}

double NodeBlockCholesky::path_blocks(int node, int& path_length) const {
  path_length = 0;
  if (!factorised_ || !analysed()) return 0.0;
  double blocks = 0.0;
  for (int j = position_[static_cast<std::size_t>(node)]; j >= 0; j = parent_[static_cast<std::size_t>(j)]) {
    blocks += column_start_[static_cast<std::size_t>(j) + 1] - column_start_[static_cast<std::size_t>(j)];
    ++path_length;
  }
  return blocks;
}

void NodeBlockCholesky::inverse_factor_columns(int node, std::vector<int>& path, std::vector<double>& columns) const {
  path.clear();
  columns.clear();
  if (!factorised_ || !analysed()) return;
  assert(node >= 0 && node < nodes_);
  switch (size_) {
    case 1: path_columns<1>(node, path, columns); break;
    case 2: path_columns<2>(node, path, columns); break;
    case 3: path_columns<3>(node, path, columns); break;
    case 4: path_columns<4>(node, path, columns); break;
    case 5: path_columns<5>(node, path, columns); break;
    case 6: path_columns<6>(node, path, columns); break;
    default: break;
  }
}

Eigen::VectorXd NodeBlockCholesky::solve_transposed_factor(const Eigen::VectorXd& y) const {
  if (!factorised_ || !analysed()) return Eigen::VectorXd::Constant(y.size(), std::numeric_limits<double>::quiet_NaN());
  const int g = size_;
  assert(y.size() == static_cast<Eigen::Index>(nodes_) * g);
  Eigen::VectorXd x = y;
  switch (size_) {
    case 1: solve_blocks<1>(x.data(), false); break;
    case 2: solve_blocks<2>(x.data(), false); break;
    case 3: solve_blocks<3>(x.data(), false); break;
    case 4: solve_blocks<4>(x.data(), false); break;
    case 5: solve_blocks<5>(x.data(), false); break;
    case 6: solve_blocks<6>(x.data(), false); break;
    default: break;
  }
  Eigen::VectorXd out(y.size());
  for (int k = 0; k < nodes_; ++k)
    for (int t = 0; t < g; ++t) out[order_[static_cast<std::size_t>(k)] * g + t] = x[k * g + t];
  return out;
}

double NodeBlockCholesky::pivot_ratio() const {
  if (!factorised_ || !analysed()) return 0.0;
  // diagonal_ holds the inverses of L's diagonal blocks, whose diagonal entries are 1 / L_ii: the
  // pivot L_ii^2 is the inverse square of each.
  const std::size_t g = static_cast<std::size_t>(size_);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(nodes_); ++k)
    for (std::size_t t = 0; t < g; ++t) {
      const double inverse = diagonal_[k * g * g + t * g + t];
      const double pivot = 1.0 / (inverse * inverse);
      smallest = std::min(smallest, pivot);
      largest = std::max(largest, pivot);
    }
  return largest > 0.0 ? smallest / largest : 0.0;
}

Eigen::VectorXd NodeBlockCholesky::solve(const Eigen::VectorXd& b) const {
  if (!factorised_ || !analysed()) return Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
  const int g = size_;
  assert(b.size() == static_cast<Eigen::Index>(nodes_) * g);
  Eigen::VectorXd x(b.size());  // in elimination order
  for (int k = 0; k < nodes_; ++k)
    for (int t = 0; t < g; ++t) x[k * g + t] = b[order_[static_cast<std::size_t>(k)] * g + t];
  switch (size_) {
    case 1: solve_blocks<1>(x.data()); break;
    case 2: solve_blocks<2>(x.data()); break;
    case 3: solve_blocks<3>(x.data()); break;
    case 4: solve_blocks<4>(x.data()); break;
    case 5: solve_blocks<5>(x.data()); break;
    case 6: solve_blocks<6>(x.data()); break;
    default: break;
  }
  Eigen::VectorXd out(b.size());
  for (int k = 0; k < nodes_; ++k)
    for (int t = 0; t < g; ++t) out[order_[static_cast<std::size_t>(k)] * g + t] = x[k * g + t];
  return out;
}

}  // namespace shatter
