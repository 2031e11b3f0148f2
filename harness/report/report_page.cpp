#include "harness/report/report_page.h"

#include "harness/accuracy/accuracy_output.h"
#include "harness/results/markdown_text.h"

#include <fmt/core.h>

#include <set>

namespace shatter {
namespace {

std::string grid_section(const GridFigures& g) {
  const ReportGrid& grid = *g.grid;
  std::string out;
  int over = 0, failed = 0;
  for (const ReportCell& c : grid.cells) {
    over += c.failed.empty() && !c.within_budget ? 1 : 0;
    failed += c.failed.empty() ? 0 : 1;
  }
  out += fmt::format("## Frame budget: {}\n\nSource: {}. Budget {:g} ms per frame; {} of {} cells over it{}.\n\n",
                     markdown_cell(grid.case_name), markdown_cell(grid.file), grid.budget_ms, over, grid.cells.size(),
                     failed > 0 ? fmt::format(", {} failed (`grid --timeout`)", failed) : std::string());
  out += fmt::format("![worst frame per cell against the budget]({})\n\n", g.heat_map);

  std::set<int> row_set, column_set;
  for (const ReportCell& c : grid.cells) {
    row_set.insert(c.prefracture);
    column_set.insert(c.runtime);
  }
  out += "Worst frame (ms; the median over repetitions of each run's slowest frame; **bold !** = over the budget):\n\n";
  out += "| pre-fracture \\ runtime |";
  for (const int r : column_set) out += fmt::format(" {} |", r);
  out += "\n|---:|";
  for (std::size_t i = 0; i < column_set.size(); ++i) out += "---:|";
  out += "\n";
  for (const int p : row_set) {
    out += fmt::format("| {} |", p);
    for (const int r : column_set) {
      std::string text = " |";
      for (const ReportCell& c : grid.cells)
        if (c.prefracture == p && c.runtime == r)
          text = !c.failed.empty() ? fmt::format(" **{} !** |", markdown_cell(c.failed))
                 : c.within_budget ? fmt::format(" {:.2f} |", c.worst_frame_ms)
                                   : fmt::format(" **{:.2f} !** |", c.worst_frame_ms);
      out += text;
    }
    out += "\n";
  }
  const ReportCell& cell = *g.cell;
  out += fmt::format("\n### Stages of cell {} x {}\n\n", cell.prefracture, cell.runtime);
  out += fmt::format("![time per stage of cell {} x {}]({})\n\n", cell.prefracture, cell.runtime, g.stage_bars);
  out += "| stage | median ms |";
  for (std::size_t k = 0; k < cell.sample_stages_ms.size(); ++k) out += fmt::format(" run {} ms |", k + 1);
  out += "\n|---|---:|";
  for (std::size_t k = 0; k < cell.sample_stages_ms.size(); ++k) out += "---:|";
  out += "\n";
  for (const auto& [stage, ms] : cell.stages_ms) {
    out += fmt::format("| {} | {:.3f} |", markdown_cell(stage), ms);
    for (const StageTimes& run : cell.sample_stages_ms) {
      double value = 0.0;
      for (const auto& [name, v] : run)
        if (name == stage) value = v;
      out += fmt::format(" {:.3f} |", value);
    }
    out += "\n";
  }
  out += "\nStage times are summed over the frames of a run (the median per stage over the runs in the first column).\n\n";
  return out;
}

std::string accuracy_section(const AccuracyFigures& a) {
  std::string out = fmt::format("## Accuracy against time\n\nSource: {}.\n\n", markdown_cell(a.accuracy->file));
  for (const ParetoFigure& f : a.charts)
    out += fmt::format("### {}: {}\n\n![{} time against error on {}]({})\n\n", markdown_cell(f.family),
                       markdown_cell(f.case_name), markdown_cell(f.family), markdown_cell(f.case_name), f.image);
  std::string tables = accuracy_to_markdown(a.accuracy->points);
  // One heading level down inside the report.
  std::string shifted;
  std::size_t start = 0;
  while (start < tables.size()) {
    std::size_t end = tables.find('\n', start);
    if (end == std::string::npos) end = tables.size();
    const std::string line = tables.substr(start, end - start);
    shifted += (line.rfind("## ", 0) == 0 ? "### Table: " + line.substr(3) : line) + "\n";
    start = end + 1;
  }
  return out + shifted + "\n";
}

std::string stability_section(const ReportStability& s) {
  std::string out = fmt::format("## Stability verdicts\n\nSource: {}.\n\n", markdown_cell(s.file));
  out += "| hazard | algorithm | kind | outcome | worst error | time ms | detail |\n|---|---|---|---|---:|---:|---|\n";
  for (const HazardResult& r : s.results)
    out += fmt::format("| {} | {} | {} | {} | {:.3g} | {:.0f} | {} |\n", markdown_cell(r.hazard), markdown_cell(r.algorithm),
                       markdown_cell(r.kind), outcome_tag(r.outcome), r.worst_error, r.time_ms, markdown_cell(r.detail));
  return out + "\n";
}

std::string table_section(const ReportTable& t) {
  std::string out = fmt::format("## Fracture table\n\nSource: {}.\n\n", markdown_cell(t.file));
  out += "| mesh | algorithm | requested | produced | median ms |\n|---|---|---:|---|---:|\n";
  for (const ReportTableRow& r : t.rows)
    out += fmt::format("| {} | {} | {} | {} | {} |\n", markdown_cell(r.mesh), markdown_cell(r.algorithm), r.fragments,
                       markdown_cell(r.outcome), r.time_ms ? fmt::format("{:.3f}", *r.time_ms) : std::string());
  return out + "\n";
}

}  // namespace

std::string report_page(const std::vector<GridFigures>& grids, const std::vector<AccuracyFigures>& accuracies,
                        const std::vector<ReportStability>& stabilities, const std::vector<ReportTable>& tables) {
  std::string out = "# shatterbench report\n\n";
  out += "Made by `shatterbench report` from the results files named in each section; the images are drawn by "
         "gnuplot from the `.dat` and `.gp` files beside them. The interactive page of the same results is "
         "`report.html` beside this file.\n\n";
  for (const GridFigures& g : grids) out += grid_section(g);
  for (const AccuracyFigures& a : accuracies) out += accuracy_section(a);
  for (const ReportStability& s : stabilities) out += stability_section(s);
  for (const ReportTable& t : tables) out += table_section(t);
  return out;
}

}  // namespace shatter
