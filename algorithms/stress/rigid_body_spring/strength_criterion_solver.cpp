#include "algorithms/stress/rigid_body_spring/strength_criterion_solver.h"

#include "algorithms/bonds/graph_components.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"

#include <algorithm>
#include <cassert>
#include <numeric>
#include <optional>

namespace shatter {

StrengthCriterionSolver::StrengthCriterionSolver(const SupportGraph& graph, const Material& material,
                                                 Criterion criterion, const SpringSolverSettings& settings)
    : graph_(graph), material_(material), criterion_(criterion), settings_(settings), stiffness_(graph, material) {}

StrengthCriterionSolver::~StrengthCriterionSolver() = default;

Result<StressResult> StrengthCriterionSolver::evaluate(const Loads& loads) {
  StressResult fresh;
  fresh.bonds.resize(graph_.bonds.size());
  std::vector<int> all(graph_.nodes.size());
  std::iota(all.begin(), all.end(), 0);
  return reevaluate(loads, fresh, all);
}

Result<StressResult> StrengthCriterionSolver::reevaluate(const Loads& loads, const StressResult& previous,
                                                         std::span<const int> touched) {
  const SupportGraph& graph = graph_;
  const Material& material = material_;
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

  // Components solved now: anchored ones holding a touched node (all of them without a previous
  // result). Falling clusters are never solved; the other anchored ones keep their previous stresses.
  std::vector<std::uint8_t> solve(components.nodes.size(), 0);
  for (std::size_t c = 0; c < components.nodes.size(); ++c) {
    if (!components.anchored[c]) {
      for (const int v : components.nodes[c]) std::fill_n(out.displacements.begin() + 6 * static_cast<std::ptrdiff_t>(v), 6, 0.0);
    } else if (dirty[c] || !has_previous) {
      solve[c] = 1;
    } else {
      for (const int b : components.bonds[c]) out.bonds[static_cast<std::size_t>(b)] = previous.bonds[static_cast<std::size_t>(b)];
    }
  }

  const std::vector<double> f = node_loads(graph, loads, material);
  if (Status s = check_node_loads(f); !s) return s.error();
  std::vector<BondForces> forces(graph.bonds.size());
  std::optional<SolverReport> report;
  // The first round of a cascade (no previous displacements) goes per component, so that a single
  // evaluation stays bit for bit what it is alone; the later rounds go through the kept cascade solver.
  if (!settings_.reference && has_previous) {
    if (!cascade_) cascade_ = std::make_unique<CascadeSolver>(material, settings_, memory_.analyses);
    // It continues the cascade solver's rounds when `previous` is its last output with more broken.
    bool continues = !cascade_displacements_.empty() && previous.displacements == cascade_displacements_ &&
                     broken != cascade_broken_;
    for (std::size_t i = 0; continues && i < broken.size(); ++i) continues = broken[i] >= cascade_broken_[i];
    report = cascade_->solve(graph, components, broken, solve, f, out.displacements, forces, continues);
  }
  if (report) {
    cascade_displacements_ = out.displacements;
    cascade_broken_ = broken;
  } else {
    cascade_displacements_.clear();
    cascade_broken_.clear();
  }
  if (!report) {
    report = SolverReport{};
    for (std::size_t c = 0; c < components.nodes.size(); ++c) {
      if (!solve[c]) continue;
      const SolverReport r = solve_component(graph, components.nodes[c], components.bonds[c], f, material, settings_,
                                             memory_, out.displacements, forces, &stiffness_);
      add_solver_report(*report, r);
    }
  }
  // Both paths (per component, cascade) are judged by the one rule: residual within the tolerance.
  judge_convergence(*report, solve_tolerance(settings_));
  out.report = *report;
  for (std::size_t c = 0; c < components.nodes.size(); ++c)
    if (solve[c])
      for (const int b : components.bonds[c])
        out.bonds[static_cast<std::size_t>(b)] = bond_stress(graph.bonds[static_cast<std::size_t>(b)],
                                                             forces[static_cast<std::size_t>(b)], material, criterion_);
  judge_finite(out);
  return out;
}

}  // namespace shatter
