// "load-path": a stress model as a plugin (docs/stress-plugins.md). Every fragment hands its load
// (weight plus point loads) to the anchors along its shortest path over the intact bonds; a bond
// carries the loads of every fragment whose path crosses it and is judged by the mean stress that
// force makes on its contact area against the material's strengths.
//
// Design note: a path's length is the sum of L / A over its bonds (Bond::length over Bond::area, 1/m),
// each bond's axial flexibility L / (E A) times E: the shortest path is the stiffest, and a load takes
// a wide contact rather than a sliver beside it. The shortest paths from the anchors (Dijkstra) form a
// forest in which every fragment hangs from one parent bond, so the force through a bond is the sum of
// the loads below it: a statically determinate share of the loads that balances every fragment's
// forces (not its moments). No linear system is solved: the report says 0 solves and the result holds
// no displacements. The force F that the bond above fragment c carries toward the anchors splits on the
// bond's unit normal n (from a to b) into the normal force N = +-F.n (tension when F pulls c away from
// its parent) and the shear force V = |F - (F.n) n|; with the contact area A,
//   utilization = safety_factor * max(|N| / (A * (N > 0 ? tensile : compressive strength)),
//                                     V / (A * shear strength)).
// Bonds on no path carry nothing; clusters with no anchor fall and carry nothing either.

#include "algorithms/bonds/graph_components.h"
#include "algorithms/registry/plugin_api.h"
#include "algorithms/stress/stress_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace {

using shatter::Error;
using shatter::Result;
using shatter::StressResult;
using shatter::SupportGraph;
using shatter::Vec3;

/// The load path of one structure. Every evaluation walks the whole graph again: it costs
/// O((nodes + bonds) log nodes), and a component no break touched comes out bit for bit as before,
/// since its paths and sums do not depend on the other components.
class LoadPathSolver final : public shatter::StressSolver {
 public:
  /// A solver for `graph` (which outlives it) made of `material`.
  LoadPathSolver(const SupportGraph& graph, const shatter::Material& material, double safety_factor)
      : graph_(graph), material_(material), safety_factor_(safety_factor) {}

  [[nodiscard]] const SupportGraph& graph() const override { return graph_; }

  [[nodiscard]] Result<StressResult> evaluate(const shatter::Loads& loads) override {
    StressResult intact;
    intact.bonds.resize(graph_.bonds.size());
    return solve(loads, intact);
  }

  [[nodiscard]] Result<StressResult> reevaluate(const shatter::Loads& loads, const StressResult& previous,
                                                std::span<const int> /*touched*/) override {
    if (previous.bonds.size() != graph_.bonds.size())
      return Error{"load-path: the previous result has " + std::to_string(previous.bonds.size()) +
                   " bonds, the structure " + std::to_string(graph_.bonds.size())};
    return solve(loads, previous);
  }

 private:
  /// The loads on each fragment, N: its weight at the material's density plus its point loads.
  [[nodiscard]] std::vector<Vec3> node_forces(const shatter::Loads& loads) const {
    std::vector<Vec3> forces;
    forces.reserve(graph_.nodes.size());
    for (const shatter::SupportNode& node : graph_.nodes)
      forces.push_back(material_.density * node.volume * loads.gravity);
    for (const shatter::PointLoad& p : loads.point_loads) forces[static_cast<std::size_t>(p.node)] += p.force;
    return forces;
  }

  /// The verdict on every bond with the bonds broken in `previous` removed.
  [[nodiscard]] Result<StressResult> solve(const shatter::Loads& loads, const StressResult& previous) const {
    if (shatter::Status s = shatter::check_material(material_); !s) return s.error();
    if (shatter::Status s = shatter::check_loads(loads, graph_); !s) return s.error();
    const std::size_t node_count = graph_.nodes.size();
    const std::size_t bond_count = graph_.bonds.size();
    for (std::size_t i = 0; i < bond_count; ++i)
      if (!(graph_.bonds[i].area > 0.0) || !std::isfinite(graph_.bonds[i].area))
        return Error{"load-path: bond " + std::to_string(i) + " has no finite positive contact area"};
    std::vector<Vec3> carried = node_forces(loads);
    for (std::size_t v = 0; v < node_count; ++v)
      if (!carried[v].allFinite()) return Error{"load-path: the load on fragment " + std::to_string(v) + " overflows"};

    StressResult out;
    out.bonds.resize(bond_count);
    std::vector<std::uint8_t> broken(bond_count, 0);
    for (std::size_t i = 0; i < bond_count; ++i) {
      out.bonds[i].broken = previous.bonds[i].broken;
      broken[i] = previous.bonds[i].broken ? 1 : 0;
    }
    out.falling_clusters = shatter::falling_clusters(shatter::graph_components(graph_, broken));

    // Shortest paths from every anchor at once. Ties go to the first bond that reached a fragment; the
    // queue pops (distance, fragment) in one total order, so the forest is deterministic.
    constexpr double kUnreached = std::numeric_limits<double>::infinity();
    std::vector<double> distance(node_count, kUnreached);
    std::vector<int> parent_bond(node_count, -1);
    std::vector<std::uint8_t> settled(node_count, 0);
    std::vector<int> order;  // fragments in the order they were settled: parents before children
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t v = 0; v < node_count; ++v)
      if (graph_.nodes[v].anchored) {
        distance[v] = 0.0;
        queue.emplace(0.0, static_cast<int>(v));
      }
    while (!queue.empty()) {
      const int v = queue.top().second;
      queue.pop();
      if (settled[static_cast<std::size_t>(v)]) continue;  // a stale entry: reached sooner since
      settled[static_cast<std::size_t>(v)] = 1;
      order.push_back(v);
      for (const int bond : graph_.node_bonds[static_cast<std::size_t>(v)]) {
        const auto w = static_cast<std::size_t>(graph_.other(bond, v));
        const shatter::Bond& e = graph_.bonds[static_cast<std::size_t>(bond)];
        const double through_v = distance[static_cast<std::size_t>(v)] + std::max(e.length, 0.0) / e.area;
        if (broken[static_cast<std::size_t>(bond)] || settled[w] || !(through_v < distance[w])) continue;
        distance[w] = through_v;
        parent_bond[w] = bond;
        queue.emplace(through_v, static_cast<int>(w));
      }
    }

    // Children before parents: each fragment's carried load is complete when it hands it on.
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const int child = *it;
      const int bond = parent_bond[static_cast<std::size_t>(child)];
      if (bond < 0) continue;  // an anchor
      const Vec3& force = carried[static_cast<std::size_t>(child)];
      carried[static_cast<std::size_t>(graph_.other(bond, child))] += force;
      out.bonds[static_cast<std::size_t>(bond)] = judge(bond, child, force);
      if (!shatter::bond_finite(out.bonds[static_cast<std::size_t>(bond)]))
        return Error{"load-path: the load carried by bond " + std::to_string(bond) + " overflows"};
    }
    return out;
  }

  /// Forces, stresses and utilization of `bond` carrying `force` (N) from fragment `child` toward the anchors.
  [[nodiscard]] shatter::BondStress judge(int bond, int child, const Vec3& force) const {
    const shatter::Bond& e = graph_.bonds[static_cast<std::size_t>(bond)];
    const double along = force.dot(e.normal);
    shatter::BondStress s;
    s.normal_force = child == e.b ? along : -along;  // + tension: the child is pulled away from its parent
    s.shear_force = (force - along * e.normal).norm();
    s.sigma = std::abs(s.normal_force) / e.area;
    s.tensile = s.normal_force > 0.0;
    s.tau = s.shear_force / e.area;
    const double normal_strength = s.tensile ? material_.tensile_strength : material_.compressive_strength;
    s.utilization = safety_factor_ * std::max(s.sigma / normal_strength, s.tau / material_.shear_strength);
    return s;
  }

  const SupportGraph& graph_;
  shatter::Material material_;
  double safety_factor_;
};

/// The model: its one setting, and a LoadPathSolver per structure.
class LoadPathModel final : public shatter::StressModel {
 public:
  /// Utilizations multiplied by `safety_factor` (> 0).
  explicit LoadPathModel(double safety_factor) : safety_factor_(safety_factor) {}

  [[nodiscard]] std::string_view name() const override { return "load-path"; }
  /// Zero loads carry nothing, and clusters with no anchor are never judged: the pipeline may skip
  /// the solve of a scene without gravity or anchors.
  [[nodiscard]] bool driven_by_loads() const override { return true; }
  /// A solver that keeps nothing between evaluations: a walk of the graph is cheap.
  [[nodiscard]] std::unique_ptr<shatter::StressSolver> make_solver(const SupportGraph& graph,
                                                                   const shatter::Material& material) const override {
    return std::make_unique<LoadPathSolver>(graph, material, safety_factor_);
  }

 private:
  double safety_factor_;
};

/// Adds "load-path" and its one setting.
void register_load_path(shatter::Registries& registries) {
  std::vector<shatter::SettingDoc> docs = {
      {"safety_factor", "", "1", "(0, 1000]",
       "every utilization is multiplied by it: 2 breaks bonds at half their strength", {}}};
  registries.stress_models.add(
      "load-path", "each fragment's load carried to the anchors along its shortest path (example plugin)", docs,
      [docs](const shatter::PluginSettings& settings) -> Result<std::unique_ptr<shatter::StressModel>> {
        const shatter::SettingsReader reader("load-path", settings, docs);
        double safety_factor = 1.0;
        if (shatter::Status s = reader.check_keys(); !s) return s.error();
        if (shatter::Status s = reader.number_above("safety_factor", 0.0, 1000.0, safety_factor); !s) return s.error();
        return std::unique_ptr<shatter::StressModel>(std::make_unique<LoadPathModel>(safety_factor));
      });
}

}  // namespace

SHATTERBENCH_PLUGIN(register_load_path)
