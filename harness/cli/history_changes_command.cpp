#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/cli/history_subcommands.h"
#include "harness/history/change_points.h"
#include "harness/history/series_csv.h"
#include "harness/history/series_points.h"
#include "harness/results/markdown_text.h"

#include <fmt/core.h>

#include <iostream>
#include <limits>
#include <memory>
#include <string>

namespace shatter::cli {
namespace {

struct ChangesOptions {
  std::string csv;
  StoreFlags store;
  SeriesFilter filter;
  std::string since;
  std::string repo;
  ChangePointSettings settings;
};

int run_csv(const ChangesOptions& o) {
  Result<LabelledSeries> series = read_series_csv(o.csv);
  if (!series) return fail_input(series.error().message);
  const std::vector<SeriesChangePoint> cps = find_change_points(series->values, o.settings);
  std::cout << fmt::format("{} points, {} change points (window {}, max p-value {}, min magnitude {})\n\n",
                           series->values.size(), cps.size(), o.settings.window, o.settings.max_pvalue,
                           o.settings.min_magnitude);
  std::cout << "| commit | index | mean before | mean after | change | p-value |\n|---|---:|---:|---:|---:|---:|\n";
  for (const SeriesChangePoint& cp : cps) {
    const double change = cp.mean_before == 0.0 ? 0.0 : cp.mean_after / cp.mean_before - 1.0;
    std::cout << fmt::format("| {} | {} | {:.6g} | {:.6g} | {:+.2f} % | {:.3g} |\n", markdown_cell(series->labels[cp.index]),
                             cp.index, cp.mean_before, cp.mean_after, 100.0 * change, cp.pvalue);
  }
  return exit_ok;
}

int run_store(const ChangesOptions& o) {
  Result<HistoryStore> store = open_store(o.store, false);
  if (!store) return fail_input(store.error().message);
  const Result<std::int64_t> since = since_time(*store, o.since, o.repo);
  if (!since) return fail_input(since.error().message);
  std::size_t stepped = 0, regressions = 0, count = 0;
  std::string table;
  Status visited = store->visit_series_runs(o.filter, *since, [&](const SeriesInfo& info, std::vector<SeriesRun>& runs) {
    const std::vector<CommitPoint> points = commit_points(runs);
    if (points.empty()) return Status{};
    ++count;
    const std::vector<SeriesChange> changes = series_changes(points, info.key.better, o.settings);
    if (!changes.empty()) ++stepped;
    for (const SeriesChange& c : changes) {
      if (c.kind == ChangeKind::regression) ++regressions;
      table += fmt::format("| {} | {} | {} | {:.6g} | {:.6g} | {:+.2f} % | {:.3g} | {} |\n", markdown_cell(series_label(info.key)),
                           c.commit.substr(0, 12), c.index, c.median_before, c.median_after, 100.0 * c.change, c.pvalue,
                           c.kind == ChangeKind::regression ? "**regression**" : change_kind_name(c.kind));
    }
    return Status{};
  });
  if (!visited) return fail_input(visited.error().message);
  std::cout << fmt::format("{} series, {} with change points, {} regression steps (window {}, max p-value {}, min "
                           "magnitude {}; {})\n\n",
                           count, stepped, regressions, o.settings.window, o.settings.max_pvalue, o.settings.min_magnitude,
                           store->name());
  if (!table.empty())
    std::cout << "| series | commit | index | median before | median after | change | p-value | kind |\n"
                 "|---|---|---:|---:|---:|---:|---:|---|\n"
              << table;
  return exit_ok;
}

}  // namespace

void add_history_changes_command(CLI::App& history, int& exit_code) {
  auto o = std::make_shared<ChangesOptions>();
  CLI::App* changes = history.add_subcommand(
      "changes", "Where each series stepped: E-divisive means as Apache Otava runs it (docs/history.md)");
  CLI::Option* csv = changes->add_option("--csv", o->csv, "A plain series instead of the store: one commit,value line per point");
  add_store_flags(changes, o->store);
  changes->get_option("--db")->excludes(csv);
  add_series_filter_flags(changes, o->filter);
  changes->add_option("--since", o->since, "Only commits at or after this one (a recorded sha prefix or a git revision)")
      ->excludes(csv);
  changes->add_option("--repo", o->repo, "The git repository that resolves --since (default: the working folder)");
  changes->add_option("--window", o->settings.window, "Points per window of the split pass")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  changes->add_option("--max-pvalue", o->settings.max_pvalue, "Largest t-test p-value of a change point")
      ->check(CLI::Range(1e-12, 1.0))
      ->capture_default_str();
  changes->add_option("--min-magnitude", o->settings.min_magnitude, "Smallest relative change of a change point")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  changes->callback([o, &exit_code] { exit_code = o->csv.empty() ? run_store(*o) : run_csv(*o); });
}

}  // namespace shatter::cli
