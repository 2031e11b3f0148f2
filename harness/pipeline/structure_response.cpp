#include "harness/pipeline/structure_response.h"

#include "algorithms/bonds/graph_components.h"
#include "algorithms/stress/propagation.h"

#include <algorithm>

namespace shatter {

Status solve_structure_stress(RunState& run, bool after_hit, StageClocks& clocks) {
  RunResult& r = run.result;
  if (!run.plan.stress) {
    r.stages.skipped(Stage::stress, "not needed (case needs)");
    return {};
  }
  if (!run.options.no_skip && run.stress_model->driven_by_loads()) {
    if (run.loads.gravity.isZero(0.0)) {
      r.stages.skipped(Stage::stress, "no gravity: nothing loads the structure, no bond can fail");
      return {};
    }
    if (run.spec.anchors.empty()) {
      r.stages.skipped(Stage::stress, "no anchors: every component falls, none is solved");
      return {};
    }
  }
  StageTimer timer(clocks, Stage::stress);
  std::vector<int> broken;
  for (std::size_t b = 0; b < r.broken.size(); ++b)
    if (r.broken[b]) broken.push_back(static_cast<int>(b));
  PropagationSettings settings;
  settings.resolve_everything = run.options.no_skip;
  // The graph is set at setup and only its broken flags change, so one solver serves the whole run
  // (under --no-skip every solve gets a new one: nothing kept from an earlier solve).
  if (!run.stress_solver || &run.stress_solver->graph() != &r.graph || run.options.no_skip)
    run.stress_solver = run.stress_model->make_solver(r.graph, run.spec.material);
  auto p = propagate(*run.stress_solver, run.loads, broken, settings);
  if (!p) return Error{run.spec.name + ": stress: " + p.error().message};
  for (std::size_t b = 0; b < r.broken.size(); ++b)
    if (p->result.bonds[b].broken) r.broken[b] = 1;
  r.stress_rounds += p->rounds;
  add_solver_report(r.solver, p->report);
  r.stages.ran(Stage::stress);
  if (after_hit && !run.options.no_skip)
    r.stages.skipped(Stage::stress, "components no broken bond touched: not re-solved between rounds");
  return {};
}

std::vector<std::vector<int>> newly_falling_clusters(const RunState& run) {
  if (!run.plan.bonds) return {};
  const GraphComponents parts = graph_components(run.result.graph, run.result.broken);
  std::vector<std::vector<int>> out;
  for (std::size_t k = 0; k < parts.nodes.size(); ++k) {
    if (parts.anchored[k]) continue;
    const std::vector<int>& nodes = parts.nodes[k];
    // Hit and fallen fragments are not standing; a standing fragment's component is all standing
    // (every bond to a hit fragment is broken, a fallen cluster was a whole component).
    if (!run.standing[static_cast<std::size_t>(nodes.front())]) continue;
    out.push_back(nodes);
  }
  return out;
}

}  // namespace shatter
