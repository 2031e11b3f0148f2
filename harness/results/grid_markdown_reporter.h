#pragma once
/// A grid's results as the Markdown printed on stdout: tables with pre-fracture counts as rows and
/// runtime counts as columns.

#include "harness/results/grid_reporter.h"

namespace shatter {

/// The tables of grid_to_markdown, or in instruction mode those of grid_instructions_markdown.
class MarkdownGridReporter final : public GridReporter {
 public:
  /// Which tables: the timed ones, or the instruction counts.
  enum class Table { time, instructions };
  /// A reporter of `table`.
  explicit MarkdownGridReporter(Table table = Table::time) : table_(table) {}
  /// "markdown" (or "instructions-markdown").
  [[nodiscard]] std::string_view format() const override {
    return table_ == Table::time ? "markdown" : "instructions-markdown";
  }
  /// The tables of the report's grid.
  [[nodiscard]] std::string render(const GridReport& report) const override;

 private:
  Table table_;
};

/// Each cell its worst frame in ms, marked "**x.xx !**" when over budget ("**timeout after 2 s !**"
/// when failed); then the latency table (latency, bodies, particles); then one table per figure whose
/// spec asks for Markdown (kFigureInMarkdown), each cell its summary; then "What the worst frame is
/// made of" (per cell the frame of cell_worst_frame and its largest stages, when the samples hold
/// per-frame stage times); then the verdict lines.
std::string grid_to_markdown(const GridResult& grid, const std::string& case_name);

/// The instruction-mode table: each cell the median over repetitions of its largest frame's retired
/// instructions, in millions.
std::string grid_instructions_markdown(const GridResult& grid, const std::string& case_name);

}  // namespace shatter
