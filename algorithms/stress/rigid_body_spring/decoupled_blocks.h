#pragma once
/// Splitting K u = f into independent systems over the connected components of K's graph.
///
/// Design note: a planar structure loaded in its plane (a wall under gravity) has stiffness in which
/// the in-plane unknowns (two translations, one rotation) and the out-of-plane ones never couple, but
/// the bond frames come from atan2, so the couplings are 1e-17 instead of exact zeros. Dropping the
/// entries below a round-off tolerance relative to the diagonal (|K_ij| <= t sqrt(K_ii K_jj)) splits K
/// into two halves: each half factorises with 1/8 of the flops of the whole, and a half with no load
/// has the solution zero, so it is never solved. The solver iterates against the full K afterwards,
/// so what was dropped is still accounted for in the reported residual.

#include <Eigen/SparseCore>

#include <span>
#include <vector>

namespace shatter {

/// Unknowns grouped by connected component of K's graph without the entries with
/// |K_ij| <= tolerance sqrt(K_ii K_jj); each block sorted ascending, blocks ordered by first unknown.
/// `k` holds both triangles. tolerance 0 keeps every nonzero.
std::vector<std::vector<int>> decoupled_blocks(const Eigen::SparseMatrix<double>& k, double tolerance);

/// The principal submatrix K(block, block) without the dropped entries: its lower triangle only when
/// `lower_only`, else both. `position` maps a global unknown to its index in `block` (only the
/// entries of `block` are read).
Eigen::SparseMatrix<double> block_matrix(const Eigen::SparseMatrix<double>& k, std::span<const int> block,
                                         std::span<const int> position, double tolerance, bool lower_only);

/// One group id per unknown of `unknowns` (ascending global indices, 6 per node as the stiffness
/// assemblies number them): consecutive ids from 0, one per node, for SparseCholesky::analyze.
std::vector<int> node_groups(std::span<const int> unknowns);

}  // namespace shatter
