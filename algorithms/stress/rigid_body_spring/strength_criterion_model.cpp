#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

#include "algorithms/bonds/graph_components.h"
#include "algorithms/stress/rigid_body_spring/cascade_solver.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <optional>

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
  if (!settings_.reference) {
    // The first solve of a graph goes per component (a single evaluation stays bit for bit what it
    // was); the result carries a cascade solver, built and used from the next round on while it fits
    // (same graph, material, settings).
    auto state = std::dynamic_pointer_cast<CascadeSolver>(previous.solver_state);
    if (state && state->fits(graph, material, settings_)) {
      report = state->solve(graph, components, broken, solve, f, out.displacements, forces);
    } else {
      state = std::make_shared<CascadeSolver>(graph, material, settings_);
    }
    out.solver_state = std::move(state);
  }
  if (!report) {
    report = SolverReport{};
    for (std::size_t c = 0; c < components.nodes.size(); ++c) {
      if (!solve[c]) continue;
      const SolverReport r = solve_component(graph, components.nodes[c], components.bonds[c], f, material, settings_,
                                             out.displacements, forces);
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

std::vector<SettingDoc> spring_solver_setting_docs() {
  return {{"tolerance", "", "1e-06", "(0, 1]", "relative residual |K u - f| / |f| a converged solve may leave (or cg_tolerance, if larger)", {}},
          {"max_iterations", "iterations", "20000", "[1, 1000000000]", "CG iterations per block before giving up", {}},
          {"cg_tolerance", "", "1e-10", "(0, 1]", "relative residual at which CG stops, per block", {}},
          {"cg_only", "", "false", "true or false", "solve every block by CG, factorise none", {}}};
}

Result<SpringSolverSettings> read_spring_solver_settings(std::string_view model, const PluginSettings& settings) {
  const std::vector<SettingDoc> docs = spring_solver_setting_docs();
  const SettingsReader r(model, settings, docs);
  SpringSolverSettings s;
  bool cg_only = false;
  if (Status st = r.check_keys(); !st) return st.error();
  if (Status st = r.number_above("tolerance", 0.0, 1.0, s.residual_tolerance); !st) return st.error();
  if (Status st = r.integer("max_iterations", 1, 1000000000, s.cg_max_iterations); !st) return st.error();
  if (Status st = r.number_above("cg_tolerance", 0.0, 1.0, s.cg_tolerance); !st) return st.error();
  if (Status st = r.flag("cg_only", cg_only); !st) return st.error();
  if (cg_only) s.direct_max_flops = -1.0;
  return s;
}

namespace {

/// Registers the rigid-body-spring model judged by `criterion` under `name`.
void register_criterion(StressModelRegistry& registry, const char* name, const char* description,
                        Criterion criterion) {
  registry.add(name, description, spring_solver_setting_docs(),
               [name, criterion](const PluginSettings& settings) -> Result<std::unique_ptr<StressModel>> {
                 Result<SpringSolverSettings> s = read_spring_solver_settings(name, settings);
                 if (!s) return s.error();
                 return std::unique_ptr<StressModel>(std::make_unique<StrengthCriterionModel>(criterion, *s));
               });
}

}  // namespace

void register_tresca(StressModelRegistry& registry) {
  register_criterion(registry, "tresca", "rigid-body-spring static solve, Tresca sqrt(s^2 + 4 t^2) on every bond",
                     Criterion::tresca);
}

void register_von_mises(StressModelRegistry& registry) {
  register_criterion(registry, "von-mises",
                     "rigid-body-spring static solve, von Mises sqrt(s^2 + 3 t^2) on every bond", Criterion::von_mises);
}

}  // namespace shatter
