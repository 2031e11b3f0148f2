#include "harness/results/grid_markdown_reporter.h"

#include "harness/results/worst_frame.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>

namespace shatter {
namespace {

const char* summary_name(CellSummary s) {
  switch (s) {
    case CellSummary::median: return "median";
    case CellSummary::max: return "largest";
    case CellSummary::min: return "smallest";
    case CellSummary::all: return "all";
    case CellSummary::none: break;
  }
  return "none";
}

/// A Markdown table with pre-fracture counts as rows and runtime counts as columns (in the order the
/// cells come), each cell's text from `text` (" |"-terminated by the caller's format).
std::string cell_table(const GridResult& grid, const std::function<std::string(const GridCell&)>& text) {
  std::vector<int> rows, cols;
  std::map<std::pair<int, int>, const GridCell*> at;
  for (const GridCell& c : grid.cells) {
    if (std::find(rows.begin(), rows.end(), c.prefracture) == rows.end()) rows.push_back(c.prefracture);
    if (std::find(cols.begin(), cols.end(), c.runtime) == cols.end()) cols.push_back(c.runtime);
    at[{c.prefracture, c.runtime}] = &c;
  }
  std::string out = "| pre-fracture \\ runtime |";
  for (const int c : cols) out += fmt::format(" {} |", c);
  out += "\n|---:|";
  for (std::size_t i = 0; i < cols.size(); ++i) out += "---:|";
  out += "\n";
  for (const int r : rows) {
    out += fmt::format("| {} |", r);
    for (const int c : cols) {
      const auto it = at.find({r, c});
      out += it == at.end() ? std::string(" |") : fmt::format(" {} |", text(*it->second));
    }
    out += "\n";
  }
  return out;
}

/// One table per summarised figure whose spec asks for Markdown, in the first cell's order.
std::string figure_tables(const GridResult& grid) {
  std::vector<FigureSpec> shown;
  for (const GridCell& c : grid.cells)
    for (const Figure& f : c.summaries.figures())
      if ((f.spec.outputs & kFigureInMarkdown) != 0 &&
          std::none_of(shown.begin(), shown.end(), [&](const FigureSpec& s) { return s.name == f.spec.name; }))
        shown.push_back(f.spec);
  std::string out;
  for (const FigureSpec& spec : shown) {
    out += fmt::format("\n`{}`{} ({} over repetitions)\n\n", spec.name, spec.unit.empty() ? "" : ", " + spec.unit,
                       summary_name(spec.summary));
    out += cell_table(grid, [&](const GridCell& c) {
      if (!c.failed.empty()) return std::string("**failed !**");
      const Figure* f = c.summaries.find(spec.name);
      return f != nullptr ? figure_text(*f) : std::string();
    });
  }
  return out;
}

/// Stages shown per cell in the worst-frame table.
constexpr std::size_t kWorstFrameStagesShown = 3;

/// One row per cell that has per-frame stage times: its reported worst frame (cell_worst_frame) and
/// that frame's largest stages with their share of it; empty when no cell has them.
std::string worst_frame_table(const GridResult& grid) {
  std::string rows;
  for (const GridCell& c : grid.cells) {
    if (!c.failed.empty()) continue;
    const std::optional<WorstFrame> w = cell_worst_frame(c);
    if (!w) continue;
    std::vector<std::string> parts;
    for (const auto& [stage, ms] : largest_stages(w->stages, kWorstFrameStagesShown))
      parts.push_back(fmt::format("{} {:.2f} ({:.0f} %)", stage_name(stage), ms, w->ms > 0.0 ? 100.0 * ms / w->ms : 0.0));
    rows += fmt::format("| {} x {} | {:.2f} | {} | {} | {} |\n", c.prefracture, c.runtime, w->ms, w->repetition,
                        w->frame, parts.empty() ? std::string("-") : fmt::format("{}", fmt::join(parts, " · ")));
  }
  if (rows.empty()) return {};
  return fmt::format("\nWhat the worst frame is made of: the slowest frame of the repetition whose slowest frame is "
                     "the median one, in ms, and its {} largest stages, ms (share of the frame)\n\n"
                     "| cell | worst frame | repetition | frame | largest stages |\n|---|---:|---:|---:|---|\n{}",
                     kWorstFrameStagesShown, rows);
}

}  // namespace

std::string grid_to_markdown(const GridResult& grid, const std::string& case_name) {
  std::string out;
  if (!grid.cells.empty()) {
    const GridCell& first = grid.cells.front();
    out += fmt::format("Case `{}`: pre-fracture {}, runtime {}, stress {}; worst frame in ms (median over {} "
                       "repetitions of each one's slowest of {} frames); budget {} ms; schedule {}{}\n\n",
                       case_name, first.prefracturer, first.fracturer, first.stress, grid.repetitions, grid.frames,
                       grid.budget_ms, first.schedule,
                       grid.threads > 1 ? fmt::format("; {} threads per event", grid.threads) : std::string());
  }
  out += cell_table(grid, [](const GridCell& c) {
    if (!c.failed.empty()) return fmt::format("**{} !**", c.failed);
    return c.within_budget ? fmt::format("{:.2f}", c.worst_frame_ms) : fmt::format("**{:.2f} !**", c.worst_frame_ms);
  });
  if (!grid.cells.empty()) {
    out += fmt::format("\nLatency, trigger to visible at 60 Hz: ms (frames), budget {} ms; bodies at the end / peak; "
                       "particles peak (medians over repetitions)\n\n",
                       grid.latency_budget_ms);
    out += cell_table(grid, [](const GridCell& g) {
      if (!g.failed.empty()) return std::string("**failed !**");
      const FigureRecord& s = g.summaries;
      return fmt::format("{}{:.1f} ({:g}){} · {:g}/{:g} · {:g}", g.within_latency_budget ? "" : "**",
                         s.value_or("latency_ms", 0.0), s.value_or("latency_frames", 0.0),
                         g.within_latency_budget ? "" : " !**", s.value_or("bodies", 0.0),
                         s.value_or("bodies_peak", 0.0), s.value_or("particles_peak", 0.0));
    });
    out += figure_tables(grid);
    out += worst_frame_table(grid);
  }
  int over = 0, late = 0;
  std::vector<std::string> failed;
  for (const GridCell& c : grid.cells) {
    if (!c.failed.empty()) {
      failed.push_back(fmt::format("cell {} x {}: {}", c.prefracture, c.runtime, c.failed));
      continue;
    }
    over += c.within_budget ? 0 : 1;
    late += c.within_latency_budget ? 0 : 1;
  }
  if (!failed.empty())
    out += fmt::format("\n{} of {} cells failed (marked !): {}.\n", failed.size(), grid.cells.size(),
                       fmt::join(failed, "; "));
  if (late > 0)
    out += fmt::format("\n{} of {} cells over the {} ms latency budget (marked !).\n", late, grid.cells.size(),
                       grid.latency_budget_ms);
  if (over == 0 && failed.empty()) {
    out += fmt::format("\nAll {} cells within the {} ms budget ({:.1f} s).\n", grid.cells.size(), grid.budget_ms,
                       grid.wall_s);
  } else if (over > 0) {
    out += fmt::format("\n{} of {} cells over the {} ms budget (marked !).\n", over, grid.cells.size(), grid.budget_ms);
  }
  return out;
}

std::string grid_instructions_markdown(const GridResult& grid, const std::string& case_name) {
  std::string out = fmt::format("Case `{}`: retired instructions of the largest frame, millions (median over {} "
                                "repetitions of {} frames; counted under callgrind)\n\n",
                                case_name, grid.repetitions, grid.frames);
  out += cell_table(grid, [](const GridCell& c) {
    if (!c.failed.empty()) return fmt::format("**{} !**", c.failed);
    std::vector<double> v;
    for (const GridSample& s : c.samples)
      if (s.instructions) v.push_back(s.instructions->worst_frame);
    return fmt::format("{:.3f}", median_of(v) / 1e6);
  });
  return out;
}

std::string MarkdownGridReporter::render(const GridReport& r) const {
  return table_ == Table::time ? grid_to_markdown(r.grid, r.case_name) : grid_instructions_markdown(r.grid, r.case_name);
}

}  // namespace shatter
