#include "harness/results/grid_junit_reporter.h"

#include "harness/results/cell_checks.h"
#include "harness/results/run_context.h"

#include <fmt/core.h>

namespace shatter {

JunitSuite grid_junit_suite(const GridReport& report) {
  const GridResult& grid = report.grid;
  // Instruction mode times are valgrind's, not the game's: the budgets apply to time mode only.
  const bool instructions = grid.metric == "instructions";
  JunitSuite suite{"shatterbench.grid." + report.case_name, {}, junit_timestamp(report.context.date),
                   report.context.hostname, {}};
  suite.properties = {{"shatterbench", shatterbench_version()},
                      {"commit", report.context.commit},
                      {"fingerprint", report.context.fingerprint},
                      {"budget_ms", fmt::format("{:g}", grid.budget_ms)},
                      {"latency_budget_ms", fmt::format("{:g}", grid.latency_budget_ms)},
                      {"repetitions", std::to_string(grid.repetitions)},
                      {"frames", std::to_string(grid.frames)}};
  for (const GridCell& cell : grid.cells) {
    // The test's time is the time the cell took; its frame times are properties.
    JunitCase jc{fmt::format("cell {} x {}", cell.prefracture, cell.runtime), suite.name, cell.wall_s, {}, {}, {}, {}};
    if (!cell.failed.empty()) {
      jc.failure = cell.failed;
      jc.failure_type = "run";
    } else if (const std::vector<std::string> checks = failed_cell_checks(cell); !checks.empty()) {
      jc.failure = "check failed: " + checks.front();
      jc.failure_type = "check";
      for (std::size_t i = 1; i < checks.size(); ++i) jc.failure_detail += (i > 1 ? "\n" : "") + checks[i];
    } else if (!instructions && !cell.within_budget) {
      jc.failure = fmt::format("worst frame {:.3f} ms > budget {:g} ms", cell.worst_frame_ms, grid.budget_ms);
      jc.failure_type = "budget";
    } else if (!instructions && !cell.within_latency_budget) {
      jc.failure = fmt::format("latency {:.3f} ms > budget {:g} ms", cell.summaries.value_or("latency_ms", 0.0),
                               grid.latency_budget_ms);
      jc.failure_type = "latency";
    }
    if (cell.failed.empty()) {
      jc.properties.emplace_back("worst_frame_ms", fmt::format("{:.6f}", cell.worst_frame_ms));
      jc.properties.emplace_back("event_ms", fmt::format("{:.6f}", cell.event_ms));
    }
    for (const Figure& f : cell.summaries.figures())
      if ((f.spec.outputs & kFigureInJunit) != 0) jc.properties.emplace_back(f.spec.name, figure_text(f));
    suite.cases.push_back(std::move(jc));
  }
  return suite;
}

std::string JunitGridReporter::render(const GridReport& report) const { return junit_xml({grid_junit_suite(report)}); }

}  // namespace shatter
