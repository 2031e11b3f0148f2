#pragma once
/// AMD ordering of the graph between the nodes of a stiffness matrix, each node's unknowns kept
/// together.
///
/// Design note: the unknowns of one rigid body couple to the same neighbours, so ordering the graph
/// between nodes gives the fill of ordering the unknowns (docs/stress.md, section 3) at a fraction of
/// the cost (483 instead of 1,449 AMD nodes for a 967-bond wall's in-plane half). Both sparse
/// Cholesky factorisations (node_block_cholesky.h, supernodal_cholesky.h) order by it.

#include <Eigen/SparseCore>

#include <optional>
#include <span>
#include <vector>

namespace shatter {

/// The nodes of `lower` (the lower triangle of a symmetric matrix, compressed columns) in AMD
/// elimination order. `groups` holds one node id per column, non-decreasing with the column, ids from 0
/// on. Empty when AMD fails.
std::optional<std::vector<int>> node_amd_order(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups);

}  // namespace shatter
