#pragma once
/// The seed's stress propagation (dissertation section 8.2, tests 79-90 of its Appendix D), kept
/// faithful for comparison: pieces joined by connections, some of them roots (anchored).
///
/// Design note: the seed does not compute forces. "Checking the forces on a piece's connections" is a
/// count rule: a piece stays while it keeps enough of the connections it started with,
///   intact >= required = max(min_connections, min_support_fraction * original),
/// roots always stay. PartDestroyed removes a piece, re-checks its neighbours (PropagateStress; a piece
/// that fails is destroyed in turn), then runs FindCluster (a depth-first search) from every neighbour
/// of a destroyed piece: a cluster holding no root is a floating cluster and falls. The seed's rule has
/// no areas, masses or materials; its own future-work section names that as the limitation.

#include "algorithms/bonds/support_graph.h"

#include <cstdint>
#include <vector>

namespace shatter {

/// The count rule's thresholds.
struct ConnectionCountSettings {
  double min_support_fraction = 0.5;  ///< share of its original connections a piece must keep, in [0, 1]
  int min_connections = 1;            ///< connections a non-root piece must keep, >= 0
};

/// What one PartDestroyed call did.
struct DestroyOutcome {
  std::vector<int> destroyed;                     ///< the piece, then every piece the count rule removed
  std::vector<std::vector<int>> falling_clusters; ///< clusters left with no root, each sorted
};

/// Pieces, their connections and roots; the state of the seed's runtime destruction.
class ConnectionGraph {
 public:
  /// `neighbours`: symmetric adjacency (#pieces lists); `roots`: #pieces flags.
  ConnectionGraph(std::vector<std::vector<int>> neighbours, std::vector<std::uint8_t> roots,
                  ConnectionCountSettings settings = {});
  /// The connections of a support graph (one per bonded pair), anchored nodes as roots.
  static ConnectionGraph from_support_graph(const SupportGraph& graph, ConnectionCountSettings settings = {});

  /// Seed's PartDestroyed: destroys `piece`, propagates, and returns what fell.
  DestroyOutcome part_destroyed(int piece);
  /// Seed's PropagateStress: the live neighbours of `piece` that no longer have enough support.
  [[nodiscard]] std::vector<int> propagate_stress(int piece) const;
  /// Seed's FindCluster: every live piece reachable from `piece` over intact connections, sorted.
  [[nodiscard]] std::vector<int> find_cluster(int piece) const;

  /// Connections `piece` still has.
  [[nodiscard]] int connection_count(int piece) const { return intact_[static_cast<std::size_t>(piece)]; }
  /// Connections the count rule requires `piece` to keep (0 for roots).
  [[nodiscard]] double required(int piece) const;
  /// True when `piece` keeps enough connections (roots always).
  [[nodiscard]] bool supported(int piece) const { return connection_count(piece) >= required(piece); }
  /// True once `piece` was destroyed or fell.
  [[nodiscard]] bool gone(int piece) const { return gone_[static_cast<std::size_t>(piece)] != 0; }

 private:
  std::vector<std::vector<int>> neighbours_;
  std::vector<std::uint8_t> roots_;
  std::vector<int> original_;
  std::vector<int> intact_;
  std::vector<std::uint8_t> gone_;
  ConnectionCountSettings settings_;
};

}  // namespace shatter
