#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

#include "algorithms/bonds/graph_components.h"

#include <algorithm>
#include <numeric>

namespace shatter {

Result<StressResult> StrengthCriterionModel::evaluate(const SupportGraph& graph, const Loads& loads,
                                                      const Material& material) const {
  StressResult fresh;
  fresh.bonds.resize(graph.bonds.size());
  std::vector<int> all(graph.nodes.size());
  std::iota(all.begin(), all.end(), 0);
  return reevaluate(graph, loads, material, fresh, all);
}

Result<StressResult> StrengthCriterionModel::reevaluate(const SupportGraph& graph, const Loads& loads,
                                                        const Material& material, const StressResult& previous,
                                                        std::span<const int> touched) const {
  if (Status s = check_material(material); !s) return s.error();
  if (Status s = check_loads(loads, graph); !s) return s.error();
  assert(previous.bonds.size() == graph.bonds.size());

  std::vector<std::uint8_t> broken(graph.bonds.size(), 0);
  for (std::size_t i = 0; i < broken.size(); ++i) broken[i] = previous.bonds[i].broken ? 1 : 0;
  const GraphComponents components = graph_components(graph, broken);
  std::vector<std::uint8_t> dirty(components.nodes.size(), 0);
  for (const int v : touched) dirty[static_cast<std::size_t>(components.component_of[static_cast<std::size_t>(v)])] = 1;

  StressResult out;
  out.bonds.resize(graph.bonds.size());
  for (std::size_t i = 0; i < broken.size(); ++i) out.bonds[i].broken = broken[i] != 0;
  const bool has_previous = previous.displacements.size() == 6 * graph.nodes.size();
  out.displacements = has_previous ? previous.displacements : std::vector<double>(6 * graph.nodes.size(), 0.0);
  out.falling_clusters = falling_clusters(components);

  const std::vector<double> f = node_loads(graph, loads, material);
  std::vector<BondForces> forces(graph.bonds.size());
  for (std::size_t c = 0; c < components.nodes.size(); ++c) {
    const std::vector<int>& nodes = components.nodes[c];
    const std::vector<int>& bonds = components.bonds[c];
    if (!components.anchored[c]) {
      // Free fall: no static stress, and the singular system is never assembled.
      for (const int v : nodes) std::fill_n(out.displacements.begin() + 6 * static_cast<std::ptrdiff_t>(v), 6, 0.0);
      continue;
    }
    if (!dirty[c] && has_previous) {
      for (const int b : bonds) out.bonds[static_cast<std::size_t>(b)] = previous.bonds[static_cast<std::size_t>(b)];
      continue;
    }
    const SolverReport r = solve_component(graph, nodes, bonds, f, material, settings_, out.displacements, forces);
    out.report.solves += r.solves;
    out.report.iterations += r.iterations;
    out.report.converged = out.report.converged && r.converged;
    out.report.residual = std::max(out.report.residual, r.residual);
    out.report.unknowns = std::max(out.report.unknowns, r.unknowns);
    for (const int b : bonds)
      out.bonds[static_cast<std::size_t>(b)] = bond_stress(graph.bonds[static_cast<std::size_t>(b)],
                                                           forces[static_cast<std::size_t>(b)], material, criterion_);
  }
  return out;
}

void register_tresca(StressModelRegistry& registry) {
  registry.add("tresca", "rigid-body-spring static solve, Tresca sqrt(s^2 + 4 t^2) on every bond",
               [] { return std::make_unique<StrengthCriterionModel>(Criterion::tresca); });
}

void register_von_mises(StressModelRegistry& registry) {
  registry.add("von-mises", "rigid-body-spring static solve, von Mises sqrt(s^2 + 3 t^2) on every bond",
               [] { return std::make_unique<StrengthCriterionModel>(Criterion::von_mises); });
}

}  // namespace shatter
