#pragma once
/// The figures a destruction run records beside its timings (figure_record.h), in the order of a
/// sample in the results JSON: the one list that says what each figure is, how a cell summarises it
/// and where its summary sits in the cell's JSON and CSV. The grid fills in their values
/// (grid/run_record.h); writers and readers take them from here.

#include "harness/results/figure_record.h"

#include <optional>
#include <string_view>
#include <vector>

namespace shatter {

/// `cell_order` at which a cell's `within_latency_budget` verdict is written among its summaries.
inline constexpr int kLatencyVerdictCellOrder = 2;
/// `csv_order` at which the `within_latency_budget` column is written among the figures' columns.
inline constexpr int kLatencyVerdictCsvOrder = 5;

/// Every figure of a destruction run, in sample order.
const std::vector<FigureSpec>& run_figure_specs();

/// The spec of the run figure `name`, or none for a figure this build does not know.
std::optional<FigureSpec> run_figure_spec(std::string_view name);

/// A record holding every run figure at its fallback value, in sample order: what a run starts from.
FigureRecord run_figure_defaults();

}  // namespace shatter
