#pragma once
/// "connection-count": the seed's heuristic (connection_graph.h) behind the StressModel interface.
///
/// It computes no forces: every force and stress field of a BondStress stays 0. A bond's utilization
/// is the count rule's verdict on its weaker end, max over its non-root ends of
/// required / intact connections, so it exceeds 1 exactly when an end lacks support; propagation then
/// breaks every bond of that piece, which is the seed's "set to be destroyed". Falling clusters are
/// found by the seed's depth-first search to a root.

#include "algorithms/stress/connection_count/connection_graph.h"
#include "algorithms/stress/stress_model.h"
#include "algorithms/stress/stress_model_registry.h"

namespace shatter {

/// The seed's connection-count model.
class ConnectionCountModel final : public StressModel {
 public:
  /// The model with the count rule's `settings`.
  explicit ConnectionCountModel(ConnectionCountSettings settings = {}) : settings_(settings) {}

  [[nodiscard]] std::string_view name() const override { return "connection-count"; }
  /// The count rule ignores loads and judges unanchored pieces too.
  [[nodiscard]] bool driven_by_loads() const override { return false; }
  /// A solver that keeps nothing: counts are cheap, and every evaluation re-checks the whole graph
  /// whatever `touched` holds.
  [[nodiscard]] std::unique_ptr<StressSolver> make_solver(const SupportGraph& graph,
                                                          const Material& material) const override;

 private:
  ConnectionCountSettings settings_;
};

/// Registers "connection-count" (settings: min_support_fraction in [0, 1], min_connections >= 0).
void register_connection_count(StressModelRegistry& registry);

}  // namespace shatter
