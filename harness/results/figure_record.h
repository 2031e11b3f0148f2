#pragma once
/// The record of named figures of one run, as Google Benchmark's user counters: each figure says its
/// name, value, kind, unit, how a grid cell summarises it over repetitions and which outputs show it,
/// and every writer and reader of results handles it without code of its own for that figure.
///
/// Design note: the timing core of a sample (every frame, the stage times, the event frame) keeps
/// typed fields, as Google Benchmark keeps `real_time` and `cpu_time` beside its counters: compare,
/// report and the gate read them by type. Everything else a run counts (fragments, bodies, latency,
/// particles, solver figures) is a figure of the record. A figure's name is its key in the results
/// JSON; a dot nests it (`solver.residual` is `"solver": {"residual": ...}`). The place of a summary
/// in a cell's JSON and CSV (`cell_order`, `csv_order`) keeps the layout of existing result files;
/// a new figure goes after the known ones, in every output, with no edit elsewhere.

#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// How a figure's value is written and read.
enum class FigureKind {
  integer,  ///< a whole number (JSON integer)
  number,   ///< a double (JSON number)
  flag,     ///< true or false (stored as 1 or 0)
};

/// How a grid cell summarises a figure over its repetitions.
enum class CellSummary {
  none,    ///< not summarised: per repetition only
  median,  ///< median over repetitions (a number whatever the figure's kind)
  max,     ///< largest over repetitions
  min,     ///< smallest over repetitions
  all,     ///< true when true in every repetition (flags)
};

/// Outputs that show a figure beyond the results JSON (which holds every figure). Bits.
enum FigureOutputs : unsigned {
  kFigureInJsonOnly = 0,      ///< the results JSON only
  kFigureInGbench = 1u << 0,  ///< a user counter of the cell's `worst_frame` entries (Google Benchmark JSON)
  kFigureInJunit = 1u << 1,   ///< a property of the cell's test case (JUnit XML)
  kFigureInMarkdown = 1u << 2,  ///< a table of its own after the grid's tables (Markdown on stdout)
  kFigureEverywhere = kFigureInGbench | kFigureInJunit | kFigureInMarkdown,  ///< every output
};

/// Order value of a figure placed after every known one.
inline constexpr int kFigureLast = 1000;
/// `csv_order` of a figure without a CSV column.
inline constexpr int kNoCsvColumn = -1;

/// What a figure is; everything but its value.
struct FigureSpec {
  std::string name;                        ///< key in the results JSON; a dot nests it ("solver.residual")
  FigureKind kind = FigureKind::number;    ///< how the value is written
  std::string unit;                        ///< "ms", "frames", "bodies", "particles", ... ("" for flags)
  CellSummary summary = CellSummary::median;  ///< how a cell summarises it (none: no cell figure)
  int cell_order = kFigureLast;            ///< place of the summary among a cell's figures (JSON)
  int csv_order = kFigureLast;             ///< place of its CSV column among the figures' (kNoCsvColumn: none)
  unsigned outputs = kFigureEverywhere;    ///< FigureOutputs bits
  bool required = true;                    ///< a results file must hold it (false: files before it read `fallback`)
  double fallback = 0.0;                   ///< value of a missing optional figure
};

/// One figure: what it is and its value (flags 1 or 0; integers exact below 2^53).
struct Figure {
  FigureSpec spec;     ///< what it is
  double value = 0.0;  ///< its value, in spec.unit
};

/// An ordered list of figures with unique names: one run's (a sample), or a cell's summaries.
class FigureRecord {
 public:
  /// Appends `spec` with `value`; a figure of that name already there takes the new spec and value.
  void add(const FigureSpec& spec, double value);
  /// Sets the value of the figure `name`, which must be in the record (asserted).
  void set(std::string_view name, double value);
  /// The figure `name`, or null.
  [[nodiscard]] const Figure* find(std::string_view name) const;
  /// The value of `name`, which must be in the record (asserted).
  [[nodiscard]] double value(std::string_view name) const;
  /// The value of `name`, or `fallback` when it is not in the record.
  [[nodiscard]] double value_or(std::string_view name, double fallback) const;
  /// Every figure, in order.
  [[nodiscard]] const std::vector<Figure>& figures() const { return figures_; }
  /// True when the record holds no figure.
  [[nodiscard]] bool empty() const { return figures_.empty(); }

 private:
  std::vector<Figure> figures_;
};

/// The summaries of `samples` (one record per repetition, the first one's figures in order): every
/// figure whose spec has a summary, summarised over the repetitions that hold it, ordered by
/// `cell_order` (figures of equal order keep their record order). A median is a number.
FigureRecord summarise_figures(const std::vector<const FigureRecord*>& samples);

/// The value of a figure of `kind` as text: integers and medians with "{:g}", flags "true"/"false",
/// numbers in ms with six decimals, other numbers with "{:g}".
std::string figure_text(const Figure& figure);

}  // namespace shatter
