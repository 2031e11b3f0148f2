#include "algorithms/stress/rigid_body_spring/stiffness_pattern.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shatter {

namespace {

/// The mask of the transposed block: bit 6 k + r moves to 6 r + k. Column k (6 bits) becomes row k:
/// its bit r goes to 6 r + k, which a table spreads for all 64 columns at once.
std::uint64_t transposed(std::uint64_t mask) {
  static constexpr std::array<std::uint64_t, 64> kSpread = [] {
    std::array<std::uint64_t, 64> spread{};
    for (int v = 0; v < 64; ++v)
      for (int r = 0; r < 6; ++r)
        if ((v >> r) & 1) spread[static_cast<std::size_t>(v)] |= std::uint64_t{1} << (6 * r);
    return spread;
  }();
  std::uint64_t out = 0;
  for (int k = 0; k < 6; ++k) out |= kSpread[static_cast<std::size_t>((mask >> (6 * k)) & 0x3f)] << k;
  return out;
}

/// Set bits among the 6 of column k of a mask.
int column_count(std::uint64_t mask, int k) {
  static constexpr std::array<std::uint8_t, 64> kBits = [] {
    std::array<std::uint8_t, 64> bits{};
    for (int v = 0; v < 64; ++v)
      for (int b = 0; b < 6; ++b) bits[static_cast<std::size_t>(v)] += static_cast<std::uint8_t>((v >> b) & 1);
    return bits;
  }();
  return kBits[static_cast<std::size_t>((mask >> (6 * k)) & 0x3f)];
}

}  // namespace

std::uint64_t nonzero_mask(const Matrix6& block) {
  std::uint64_t mask = 0;
  const double* d = block.data();
#if defined(__SSE2__)
  // Two entries per compare: this runs for every block of every bond of every evaluation.
  const __m128d zero = _mm_setzero_pd();
  for (int e = 0; e < 36; e += 2)
    mask |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_cmpneq_pd(_mm_loadu_pd(d + e), zero))) << e;
#else
  for (int e = 0; e < 36; ++e) mask |= static_cast<std::uint64_t>(d[e] != 0.0) << e;
#endif
  return mask;
}

StiffnessPattern build_stiffness_pattern(int free_nodes, std::span<const std::array<int, 2>> ends,
                                         std::span<const std::array<std::uint64_t, 4>> masks) {
  const std::size_t nf = static_cast<std::size_t>(free_nodes);
  // Each column node i's row nodes (itself included), sorted: its pairs, pair_start[i] on.
  std::vector<int> pair_start(nf + 1, 0);
  for (std::size_t i = 0; i < nf; ++i) pair_start[i + 1] = 1;
  for (const auto& [a, b] : ends)
    if (a >= 0 && b >= 0) {
      ++pair_start[static_cast<std::size_t>(a) + 1];
      ++pair_start[static_cast<std::size_t>(b) + 1];
    }
  for (std::size_t i = 0; i < nf; ++i) pair_start[i + 1] += pair_start[i];
  std::vector<int> rows(static_cast<std::size_t>(pair_start.back()));
  {
    std::vector<int> next(pair_start.begin(), pair_start.end() - 1);
    for (std::size_t i = 0; i < nf; ++i) rows[static_cast<std::size_t>(next[i]++)] = static_cast<int>(i);
    for (const auto& [a, b] : ends)
      if (a >= 0 && b >= 0) {
        rows[static_cast<std::size_t>(next[static_cast<std::size_t>(a)]++)] = b;
        rows[static_cast<std::size_t>(next[static_cast<std::size_t>(b)]++)] = a;
      }
  }
  // Sort and drop repeats (two bonds between one pair of nodes) in place, column by column.
  std::vector<int> unique_start(nf + 1, 0);
  int kept = 0;
  for (std::size_t i = 0; i < nf; ++i) {
    const auto first = rows.begin() + pair_start[i], last = rows.begin() + pair_start[i + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    unique_start[i] = kept;
    const auto to = rows.begin() + kept;  // at or before first: a forward copy is safe
    kept += static_cast<int>(end - first);
    if (to != first) std::copy(first, end, to);
  }
  unique_start[nf] = kept;
  rows.resize(static_cast<std::size_t>(kept));
  const auto pair = [&](int row_node, int column_node) {
    const auto first = rows.begin() + unique_start[static_cast<std::size_t>(column_node)];
    const auto last = rows.begin() + unique_start[static_cast<std::size_t>(column_node) + 1];
    return static_cast<int>(std::lower_bound(first, last, row_node) - rows.begin());
  };

  StiffnessPattern out;
  out.pairs.resize(rows.size());
  std::uint64_t diagonal_mask = 0;
  for (int k = 0; k < 6; ++k) diagonal_mask |= std::uint64_t{1} << (7 * k);
  std::vector<int> diagonal_pair(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    diagonal_pair[i] = pair(static_cast<int>(i), static_cast<int>(i));
    out.pairs[static_cast<std::size_t>(diagonal_pair[i])].mask = diagonal_mask;
  }
  out.bond_pairs.resize(ends.size());
  for (std::size_t b = 0; b < ends.size(); ++b) {
    const int a = ends[b][0], c = ends[b][1];
    std::array<int, 4>& p = out.bond_pairs[b];
    p[0] = a >= 0 ? diagonal_pair[static_cast<std::size_t>(a)] : -1;  // (a, a)
    p[3] = c >= 0 ? diagonal_pair[static_cast<std::size_t>(c)] : -1;  // (b, b)
    p[1] = a >= 0 && c >= 0 ? pair(c, a) : -1;                        // (b, a)
    p[2] = a >= 0 && c >= 0 ? pair(a, c) : -1;                        // (a, b)
    for (std::size_t q = 0; q < 4; ++q)
      if (p[q] >= 0) out.pairs[static_cast<std::size_t>(p[q])].mask |= masks[b][q];
  }
  // K is symmetric, but a block and its mirror need not have their zeros in mirrored places (round-off
  // can cancel on one side only): each pair stores the union with its mirror's transpose, so that the
  // pattern is symmetric and a lower triangle holds every entry of K. A bond's blocks (b, a) and
  // (a, b) are mirrors, and a diagonal pair is its own.
  constexpr std::uint64_t kFull = (std::uint64_t{1} << 36) - 1;
  const auto symmetrise = [&](int p, int mirror) {
    std::uint64_t& m = out.pairs[static_cast<std::size_t>(p)].mask;
    std::uint64_t& n = out.pairs[static_cast<std::size_t>(mirror)].mask;
    if (m == kFull && n == kFull) return;  // dense blocks, as in most 3D bodies
    m |= transposed(n);
    n = transposed(m);
  };
  for (const std::array<int, 4>& p : out.bond_pairs)
    if (p[1] >= 0) symmetrise(p[1], p[2]);
  for (std::size_t i = 0; i < nf; ++i) symmetrise(diagonal_pair[i], diagonal_pair[i]);

  // Column k of node i: for each of its pairs in row order, the rows r the pair's mask holds.
  const int n = 6 * free_nodes;
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0);
  for (std::size_t i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k) {
      int count = 0;
      for (int p = unique_start[i]; p < unique_start[i + 1]; ++p) count += column_count(out.pairs[static_cast<std::size_t>(p)].mask, k);
      outer[6 * i + static_cast<std::size_t>(k) + 1] = count;
    }
  for (int c = 0; c < n; ++c) outer[static_cast<std::size_t>(c) + 1] += outer[static_cast<std::size_t>(c)];
  out.matrix.resize(n, n);
  out.matrix.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), out.matrix.outerIndexPtr());
  std::fill(out.matrix.valuePtr(), out.matrix.valuePtr() + outer.back(), 0.0);
  int* inner = out.matrix.innerIndexPtr();
  out.diagonal.assign(static_cast<std::size_t>(n), -1);
  for (std::size_t i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k) {
      int at = outer[6 * i + static_cast<std::size_t>(k)];
      for (int p = unique_start[i]; p < unique_start[i + 1]; ++p) {
        NodePairEntries& entries = out.pairs[static_cast<std::size_t>(p)];
        const int j = rows[static_cast<std::size_t>(p)];
        entries.column_start[static_cast<std::size_t>(k)] = at;
        if (j == static_cast<int>(i))  // the diagonal entry: after the rows above it in this column
          out.diagonal[6 * i + static_cast<std::size_t>(k)] = at + column_count(entries.mask & ((std::uint64_t{1} << (6 * k + k)) - 1), k);
        const std::uint64_t column = (entries.mask >> (6 * k)) & 0x3f;
        if (column == 0x3f) {  // all six rows (dense blocks)
          for (int r = 0; r < 6; ++r) inner[at + r] = 6 * j + r;
          at += 6;
          continue;
        }
        for (int r = 0; r < 6; ++r)
          if ((column >> r) & 1) inner[at++] = 6 * j + r;
      }
    }
  return out;
}

}  // namespace shatter
