#include "algorithms/stress/connection_count/connection_count_model.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace shatter {
namespace {

/// The count rule's verdict on every bond of `graph`, with the bonds of `previous` flagged broken.
Result<StressResult> count_verdicts(const SupportGraph& graph, const Loads& loads, const Material& material,
                                    const ConnectionCountSettings& settings, const StressResult& previous) {
  if (Status s = check_material(material); !s) return s.error();
  if (Status s = check_loads(loads, graph); !s) return s.error();
  if (!(settings.min_support_fraction >= 0.0 && settings.min_support_fraction <= 1.0) ||
      settings.min_connections < 0)
    return Error{"connection-count: min_support_fraction must be in [0, 1] and min_connections >= 0"};
  assert(previous.bonds.size() == graph.bonds.size());

  // Original counts from every bonded pair; intact counts from the pairs with an unbroken bond.
  ConnectionGraph original = ConnectionGraph::from_support_graph(graph, settings);
  SupportGraph intact_graph;
  intact_graph.nodes = graph.nodes;
  for (std::size_t i = 0; i < graph.bonds.size(); ++i)
    if (!previous.bonds[i].broken) intact_graph.bonds.push_back(graph.bonds[i]);
  const ConnectionGraph intact = ConnectionGraph::from_support_graph(intact_graph, settings);

  StressResult out;
  out.bonds.resize(graph.bonds.size());
  for (std::size_t i = 0; i < graph.bonds.size(); ++i) {
    BondStress& s = out.bonds[i];
    s.broken = previous.bonds[i].broken;
    if (s.broken) continue;
    for (const int end : {graph.bonds[i].a, graph.bonds[i].b}) {
      const int count = intact.connection_count(end);  // >= 1: this bond is intact
      s.utilization = std::max(s.utilization, original.required(end) / static_cast<double>(count));
    }
  }
  // Falling clusters: the seed's FindCluster from every piece not yet placed, kept when rootless.
  std::vector<std::uint8_t> placed(graph.nodes.size(), 0);
  for (int v = 0; v < graph.node_count(); ++v) {
    if (placed[static_cast<std::size_t>(v)]) continue;
    std::vector<int> cluster = intact.find_cluster(v);
    bool rooted = false;
    for (const int w : cluster) {
      placed[static_cast<std::size_t>(w)] = 1;
      rooted = rooted || graph.nodes[static_cast<std::size_t>(w)].anchored;
    }
    if (!rooted) out.falling_clusters.push_back(std::move(cluster));
  }
  return out;
}

/// The count rule on one structure; it keeps nothing between evaluations.
class ConnectionCountSolver final : public StressSolver {
 public:
  ConnectionCountSolver(const SupportGraph& graph, const Material& material, const ConnectionCountSettings& settings)
      : graph_(graph), material_(material), settings_(settings) {}

  [[nodiscard]] const SupportGraph& graph() const override { return graph_; }
  [[nodiscard]] Result<StressResult> evaluate(const Loads& loads) override {
    StressResult fresh;
    fresh.bonds.resize(graph_.bonds.size());
    return count_verdicts(graph_, loads, material_, settings_, fresh);
  }
  [[nodiscard]] Result<StressResult> reevaluate(const Loads& loads, const StressResult& previous,
                                                std::span<const int> /*touched*/) override {
    return count_verdicts(graph_, loads, material_, settings_, previous);
  }

 private:
  const SupportGraph& graph_;
  Material material_;
  ConnectionCountSettings settings_;
};

}  // namespace

std::unique_ptr<StressSolver> ConnectionCountModel::make_solver(const SupportGraph& graph,
                                                                const Material& material) const {
  return std::make_unique<ConnectionCountSolver>(graph, material, settings_);
}

void register_connection_count(StressModelRegistry& registry) {
  std::vector<SettingDoc> docs = {
      {"min_support_fraction", "", "0.5", "[0, 1]", "share of its original connections a piece must keep", {}},
      {"min_connections", "connections", "1", "[0, 1000000]", "connections a non-root piece must keep", {}}};
  registry.add("connection-count", "the seed's heuristic: count of remaining connections, DFS to a root", docs,
               [docs](const PluginSettings& settings) -> Result<std::unique_ptr<StressModel>> {
                 const SettingsReader r("connection-count", settings, docs);
                 ConnectionCountSettings c;
                 if (Status s = r.check_keys(); !s) return s.error();
                 if (Status s = r.number("min_support_fraction", 0.0, 1.0, c.min_support_fraction); !s) return s.error();
                 if (Status s = r.integer("min_connections", 0, 1000000, c.min_connections); !s) return s.error();
                 return std::unique_ptr<StressModel>(std::make_unique<ConnectionCountModel>(c));
               });
}

}  // namespace shatter
