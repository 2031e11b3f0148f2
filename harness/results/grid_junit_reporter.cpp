#include "harness/results/grid_junit_reporter.h"

#include "harness/results/cell_checks.h"

#include <fmt/core.h>

namespace shatter {

JunitSuite grid_junit_suite(const GridReport& report) {
  const GridResult& grid = report.grid;
  // Instruction mode times are valgrind's, not the game's: the budgets apply to time mode only.
  const bool instructions = grid.metric == "instructions";
  JunitSuite suite{"shatterbench.grid." + report.case_name, {}};
  for (const GridCell& cell : grid.cells) {
    JunitCase jc{fmt::format("cell {} x {}", cell.prefracture, cell.runtime), suite.name, cell.worst_frame_ms / 1000.0,
                 {}, {}};
    if (!cell.failed.empty())
      jc.failure = cell.failed;
    else if (const std::vector<std::string> checks = failed_cell_checks(cell); !checks.empty())
      jc.failure = "check failed: " + checks.front();
    else if (!instructions && !cell.within_budget)
      jc.failure = fmt::format("worst frame {:.3f} ms > budget {:g} ms", cell.worst_frame_ms, grid.budget_ms);
    else if (!instructions && !cell.within_latency_budget)
      jc.failure = fmt::format("latency {:.3f} ms > budget {:g} ms", cell.summaries.value_or("latency_ms", 0.0),
                               grid.latency_budget_ms);
    for (const Figure& f : cell.summaries.figures())
      if ((f.spec.outputs & kFigureInJunit) != 0) jc.properties.emplace_back(f.spec.name, figure_text(f));
    suite.cases.push_back(std::move(jc));
  }
  return suite;
}

std::string JunitGridReporter::render(const GridReport& report) const { return junit_xml({grid_junit_suite(report)}); }

}  // namespace shatter
