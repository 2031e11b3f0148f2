#include "harness/results/run_figures.h"

namespace shatter {
namespace {

using K = FigureKind;
using S = CellSummary;

/// A per-repetition figure with no cell summary and no CSV column; `required` false for the figures
/// that came after the first files of schema version 1 (those read as `fallback`).
FigureSpec sample_only(const char* name, K kind, const char* unit, bool required = true, double fallback = 0.0) {
  return FigureSpec{name, kind, unit, S::none, kFigureLast, kNoCsvColumn, kFigureInJsonOnly, required, fallback};
}

/// A figure a cell summarises, at `cell_order` in its JSON and `csv_order` in its CSV row.
FigureSpec summarised(const char* name, K kind, const char* unit, S summary, int cell_order, int csv_order,
                      bool required) {
  return FigureSpec{name, kind, unit, summary, cell_order, csv_order, kFigureInJsonOnly, required, 0.0};
}

std::vector<FigureSpec> make_specs() {
  return {
      sample_only("cache_hit", K::flag, ""),
      sample_only("fragments", K::integer, "fragments"),
      sample_only("hit", K::integer, "fragments"),
      sample_only("pieces", K::integer, "pieces"),
      sample_only("broken_bonds", K::integer, "bonds"),
      sample_only("falling_clusters", K::integer, "clusters"),
      summarised("bodies", K::integer, "bodies", S::median, 4, 2, true),
      sample_only("solver.solves", K::integer, "solves"),
      sample_only("solver.iterations", K::integer, "iterations"),
      sample_only("solver.converged", K::flag, ""),
      sample_only("solver.residual", K::number, "relative"),
      sample_only("solver.unknowns", K::integer, "dof"),
      summarised("latency_ms", K::number, "ms", S::median, 0, 0, false),
      summarised("latency_frames", K::integer, "frames", S::median, 1, 1, false),
      sample_only("latency_after_impact_frames", K::integer, "frames", false),
      sample_only("trigger_frame", K::integer, "frame", false, -1.0),
      sample_only("visible_frame", K::integer, "frame", false, -1.0),
      sample_only("event_steps", K::integer, "steps", false),
      summarised("largest_step_ms", K::number, "ms", S::max, 3, kNoCsvColumn, false),
      sample_only("worst_work_ms", K::number, "ms", false),
      summarised("bodies_peak", K::integer, "bodies", S::median, 5, 3, false),
      sample_only("faded", K::integer, "pieces", false),
      sample_only("particles_spawned", K::integer, "particles", false),
      summarised("particles_peak", K::integer, "particles", S::median, 6, 4, false),
  };
}

}  // namespace

const std::vector<FigureSpec>& run_figure_specs() {
  static const std::vector<FigureSpec> specs = make_specs();
  return specs;
}

std::optional<FigureSpec> run_figure_spec(std::string_view name) {
  for (const FigureSpec& s : run_figure_specs())
    if (s.name == name) return s;
  return std::nullopt;
}

FigureRecord run_figure_defaults() {
  FigureRecord out;
  for (const FigureSpec& s : run_figure_specs()) out.add(s, s.fallback);
  return out;
}

}  // namespace shatter
