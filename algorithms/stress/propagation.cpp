#include "algorithms/stress/propagation.h"

#include "algorithms/bonds/graph_components.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>

namespace shatter {

namespace {

void accumulate(SolverReport& total, const SolverReport& r) { add_solver_report(total, r); }

}  // namespace

Result<PropagationResult> propagate(StressSolver& solver, const Loads& loads, std::span<const int> initially_broken,
                                    const PropagationSettings& settings) {
  const SupportGraph& graph = solver.graph();
  if (settings.max_rounds < 0) return Error{"propagation: max_rounds must be >= 0"};
  for (const int b : initially_broken)
    if (b < 0 || b >= graph.bond_count())
      return Error{"propagation: broken bond " + std::to_string(b) + " out of range (" +
                   std::to_string(graph.bond_count()) + " bonds)"};

  PropagationResult out;
  Result<StressResult> current = Error{""};
  if (initially_broken.empty()) {
    current = solver.evaluate(loads);
  } else {
    StressResult start;
    start.bonds.resize(graph.bonds.size());
    for (const int b : initially_broken) start.bonds[static_cast<std::size_t>(b)].broken = true;
    std::vector<int> all(graph.nodes.size());
    std::iota(all.begin(), all.end(), 0);
    current = solver.reevaluate(loads, start, all);
  }
  if (!current) return current.error();
  accumulate(out.report, current->report);

  std::vector<int> failing, touched;
  while (true) {
    // Bonds are broken only on a converged solve: the utilizations of another are not an answer.
    if (!current->report.converged) break;
    failing.clear();
    for (int i = 0; i < graph.bond_count(); ++i) {
      const BondStress& s = current->bonds[static_cast<std::size_t>(i)];
      if (!s.broken && s.utilization > 1.0) failing.push_back(i);
    }
    if (failing.empty() || out.rounds >= settings.max_rounds) break;
    touched.clear();
    StressResult next = std::move(current.value());
    for (const int b : failing) {
      next.bonds[static_cast<std::size_t>(b)].broken = true;
      touched.push_back(graph.bonds[static_cast<std::size_t>(b)].a);
      touched.push_back(graph.bonds[static_cast<std::size_t>(b)].b);
    }
    if (settings.resolve_everything) {
      touched.resize(graph.nodes.size());
      std::iota(touched.begin(), touched.end(), 0);
    }
    out.break_order.push_back(failing);
    ++out.rounds;
    current = solver.reevaluate(loads, next, touched);
    if (!current) return current.error();
    accumulate(out.report, current->report);
  }
  out.result = std::move(current.value());
  std::vector<std::uint8_t> broken(graph.bonds.size());
  for (std::size_t i = 0; i < broken.size(); ++i) broken[i] = out.result.bonds[i].broken ? 1 : 0;
  out.result.falling_clusters = falling_clusters(graph_components(graph, broken));
  return out;
}

Result<PropagationResult> propagate(const StressModel& model, const SupportGraph& graph, const Loads& loads,
                                    const Material& material, std::span<const int> initially_broken,
                                    const PropagationSettings& settings) {
  const std::unique_ptr<StressSolver> solver = model.make_solver(graph, material);
  return propagate(*solver, loads, initially_broken, settings);
}

}  // namespace shatter
