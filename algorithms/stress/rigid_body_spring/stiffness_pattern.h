#pragma once
/// The compressed-column pattern of a rigid-body-spring stiffness K, and where each bond's blocks go
/// in it: shared by the per-component assembly (spring_system.h) and the cascade's (graph_stiffness.h).
///
/// Design note: a bond couples the 6 unknowns of each end to those of the other through four 6 x 6
/// blocks (bond_spring.h), but many of their entries are exact zeros: in a planar structure the
/// in-plane unknowns (two translations, one rotation) never meet the out-of-plane ones, so about two
/// thirds of the entries of dense 6 x 6 node blocks are zero in every wall. K stores, for each pair of
/// coupled nodes, only the entries some bond's block makes nonzero there or at the mirrored place (the
/// pattern stays symmetric), plus every diagonal entry (an identity row needs it). Every pass over K (the split into decoupled blocks, the gathers of the
/// factorisations, the residuals) then does a third of the work. An entry may still be zero by
/// cancellation; that is a value, not a structural zero.

#include "algorithms/stress/rigid_body_spring/bond_spring.h"

#include <Eigen/SparseCore>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// One (row node, column node) block of K: which of its 36 entries K stores (bit 6 k + r for row r,
/// column k) and, per column, the value index of the first one stored (the rest follow, by row).
struct NodePairEntries {
  std::uint64_t mask = 0;
  std::array<int, 6> column_start{};
};

struct StiffnessPattern {
  Eigen::SparseMatrix<double> matrix;   ///< the pattern, values zero; rows sorted in every column
  std::vector<int> diagonal;            ///< #unknowns: value index of each diagonal entry
  std::vector<NodePairEntries> pairs;   ///< the node pairs K stores
  /// Per bond given, the pair of each of its four blocks (bond_blocks order: (y, x) = (a, a), (b, a),
  /// (a, b), (b, b)), -1 where an end has no unknowns.
  std::vector<std::array<int, 4>> bond_pairs;
};

/// Bit (6 k + r) set where `block` has a nonzero (or NaN) at row r, column k.
std::uint64_t nonzero_mask(const Matrix6& block);

/// The pattern of K for `free_nodes` nodes of 6 unknowns (node i owns unknowns 6 i .. 6 i + 5) and the
/// bonds whose ends (free node indices, -1 for an anchored end) are `ends`, with `masks` the nonzero
/// masks of their four blocks.
StiffnessPattern build_stiffness_pattern(int free_nodes, std::span<const std::array<int, 2>> ends,
                                         std::span<const std::array<std::uint64_t, 4>> masks);

/// Adds a 6 x 6 block into `value` at the entries `pair` stores (the block is zero elsewhere).
inline void add_pair_block(double* value, const Matrix6& block, const NodePairEntries& pair) {
  for (int k = 0; k < 6; ++k) {
    double* column = value + pair.column_start[static_cast<std::size_t>(k)];
    const std::uint64_t rows = (pair.mask >> (6 * k)) & 0x3f;
    if (rows == 0x3f) {  // all six rows stored (dense blocks)
      for (int r = 0; r < 6; ++r) column[r] += block(r, k);
      continue;
    }
    for (int r = 0; r < 6; ++r)
      if ((rows >> r) & 1) *column++ += block(r, k);
  }
}

}  // namespace shatter
