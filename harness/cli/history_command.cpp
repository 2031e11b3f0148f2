#include "harness/cli/command.h"
#include "harness/history/change_points.h"
#include "harness/history/series_csv.h"

#include <fmt/core.h>

#include <iostream>
#include <memory>
#include <string>

namespace shatter::cli {
namespace {

struct ChangesOptions {
  std::string csv;
  ChangePointSettings settings;
};

/// A label as one Markdown table cell: no line breaks, no cell separators.
std::string cell(std::string text) {
  for (char& c : text)
    if (c == '|' || c == '\n' || c == '\r') c = ' ';
  return text;
}

int run_changes(const ChangesOptions& o) {
  Result<LabelledSeries> series = read_series_csv(o.csv);
  if (!series) return fail_input(series.error().message);
  const std::vector<SeriesChangePoint> cps = find_change_points(series->values, o.settings);
  std::cout << fmt::format("{} points, {} change points (window {}, max p-value {}, min magnitude {})\n\n",
                           series->values.size(), cps.size(), o.settings.window, o.settings.max_pvalue,
                           o.settings.min_magnitude);
  std::cout << "| commit | index | mean before | mean after | change | p-value |\n|---|---:|---:|---:|---:|---:|\n";
  for (const SeriesChangePoint& cp : cps) {
    const double change = cp.mean_before == 0.0 ? 0.0 : cp.mean_after / cp.mean_before - 1.0;
    std::cout << fmt::format("| {} | {} | {:.6g} | {:.6g} | {:+.2f} % | {:.3g} |\n", cell(series->labels[cp.index]),
                             cp.index, cp.mean_before, cp.mean_after, 100.0 * change, cp.pvalue);
  }
  return exit_ok;
}

}  // namespace

void add_history_command(CLI::App& app, int& exit_code) {
  CLI::App* history = app.add_subcommand("history", "Results across commits: change points of a series");
  history->require_subcommand(1);
  auto o = std::make_shared<ChangesOptions>();
  CLI::App* changes = history->add_subcommand(
      "changes", "Where a series steps: E-divisive means as Apache Otava runs it (docs/history.md)");
  changes->add_option("--csv", o->csv, "A plain series, one commit,value line per point in order")->required();
  changes->add_option("--window", o->settings.window, "Points per window of the split pass")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  changes->add_option("--max-pvalue", o->settings.max_pvalue, "Largest t-test p-value of a change point")
      ->check(CLI::Range(1e-12, 1.0))
      ->capture_default_str();
  changes->add_option("--min-magnitude", o->settings.min_magnitude, "Smallest relative change of a change point")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  changes->callback([o, &exit_code] { exit_code = run_changes(*o); });
}

}  // namespace shatter::cli
