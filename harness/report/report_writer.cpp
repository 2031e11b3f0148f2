#include "harness/report/report_writer.h"

#include "harness/report/heat_map_plot.h"
#include "harness/report/html/report_html.h"
#include "harness/report/pareto_plot.h"
#include "harness/report/report_page.h"
#include "harness/report/stage_bars_plot.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_folder.h"

#include <fmt/core.h>

#include <algorithm>
#include <set>

namespace shatter {
namespace fs = std::filesystem;

namespace {

/// `name` as a file-name part: letters, digits and '-' kept, anything else '-'; made unique in `used`.
std::string stem_part(const std::string& name, std::set<std::string>& used) {
  std::string out;
  for (const char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '-';
  if (out.empty()) out = "case";
  std::string unique = out;
  for (int k = 2; used.count(unique); ++k) unique = fmt::format("{}-{}", out, k);
  used.insert(unique);
  return unique;
}

Result<const ReportCell*> pick_cell(const ReportGrid& grid, const ChosenCell& chosen) {
  if (chosen) {
    for (const ReportCell& c : grid.cells)
      if (c.prefracture == chosen->first && c.runtime == chosen->second) {
        if (!c.failed.empty())
          return Error{fmt::format("--cell: cell {} x {} in {} failed ({}): it has no stage times", c.prefracture,
                                   c.runtime, grid.file, c.failed)};
        return &c;
      }
    return Error{fmt::format("--cell: no cell {} x {} in {}", chosen->first, chosen->second, grid.file)};
  }
  const ReportCell* best = nullptr;  // the largest cell that ran
  for (const ReportCell& c : grid.cells)
    if (c.failed.empty() &&
        (best == nullptr || std::pair(c.prefracture, c.runtime) > std::pair(best->prefracture, best->runtime)))
      best = &c;
  if (best == nullptr) return Error{fmt::format("{}: every cell failed: no stage times to show", grid.file)};
  return best;
}

Status fill(const ReportInputs& inputs, const fs::path& folder, const ChosenCell& chosen) {
  std::vector<GridFigures> grids;
  std::set<std::string> used;
  for (const ReportGrid& grid : inputs.grids) {
    GridFigures g;
    g.grid = &grid;
    const std::string part = stem_part(grid.case_name, used);
    Result<const ReportCell*> cell = pick_cell(grid, chosen);
    if (!cell) return cell.error();
    g.cell = *cell;
    Result<std::string> heat = plot_heat_map(grid, folder, "grid-" + part);
    if (!heat) return Error{grid.file + ": heat map: " + heat.error().message};
    g.heat_map = *heat;
    Result<std::string> bars = plot_stage_bars(*g.cell, grid.case_name, grid.frames, folder, "stages-" + part);
    if (!bars) return Error{grid.file + ": stage bars: " + bars.error().message};
    g.stage_bars = *bars;
    grids.push_back(g);
  }
  std::vector<AccuracyFigures> accuracies;
  std::set<std::string> used_charts;
  for (const ReportAccuracy& a : inputs.accuracies) {
    AccuracyFigures figures;
    figures.accuracy = &a;
    std::vector<std::pair<std::string, std::string>> groups;  // (family, case) in file order
    for (const AccuracyPoint& p : a.points)
      if (p.error && std::find(groups.begin(), groups.end(), std::pair(p.family, p.case_name)) == groups.end())
        groups.emplace_back(p.family, p.case_name);
    for (const auto& [family, case_name] : groups) {
      const std::string stem = "pareto-" + stem_part(family + "-" + case_name, used_charts);
      Result<std::string> image = plot_pareto(a.points, family, case_name, folder, stem);
      if (!image) return Error{a.file + ": " + image.error().message};
      figures.charts.push_back({family, case_name, *image});
    }
    accuracies.push_back(std::move(figures));
  }
  const std::string markdown = report_page(grids, accuracies, inputs.stabilities, inputs.tables);
  const std::string html = report_html(inputs);
  const FileContent pages[] = {{folder / "report.md", markdown}, {folder / "report.html", html}};
  return write_files_atomically(pages);
}

}  // namespace

Status write_report(const ReportInputs& inputs, const fs::path& dir, const ChosenCell& cell) {
  return write_folder_atomically(dir, [&](const fs::path& staging) { return fill(inputs, staging, cell); });
}

}  // namespace shatter
