#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/cli/history_subcommands.h"
#include "harness/history/series_points.h"
#include "harness/results/markdown_text.h"

#include <fmt/chrono.h>
#include <fmt/core.h>

#include <algorithm>
#include <ctime>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <string>

namespace shatter::cli {
namespace {

struct ShowOptions {
  StoreFlags store;
  SeriesFilter filter;
  int last = 20;
  ChangePointSettings settings;
};

/// The medians as a line of block characters, lowest to highest over their own range.
std::string sparkline(const std::vector<double>& values) {
  static const char* const kBlocks[] = {"▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"};
  if (values.empty()) return {};
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  std::string out;
  for (double v : values) {
    const int level = *hi > *lo ? static_cast<int>(std::lround(7.0 * (v - *lo) / (*hi - *lo))) : 0;
    out += kBlocks[std::clamp(level, 0, 7)];
  }
  return out;
}

std::string date_of(std::int64_t t) {
  return fmt::format("{:%Y-%m-%d %H:%M}", fmt::gmtime(static_cast<std::time_t>(t)));
}

int run_show(const ShowOptions& o) {
  Result<HistoryStore> store = open_store(o.store, false);
  if (!store) return fail_input(store.error().message);
  // The shown commits and a window before them, so that a step near the first shown commit is found.
  std::int64_t since = std::numeric_limits<std::int64_t>::min();
  Result<std::optional<std::int64_t>> from = store->recent_commit_time(o.filter.case_name, o.last + o.settings.window - 1);
  if (!from) return fail_input(from.error().message);
  if (*from) since = **from;
  std::size_t shown = 0;
  std::string page;
  Status visited = store->visit_series_runs(o.filter, since, [&](const SeriesInfo& info, std::vector<SeriesRun>& runs) {
    const std::vector<CommitPoint> points = commit_points(runs);
    if (points.empty()) return Status{};
    ++shown;
    std::set<std::size_t> steps;
    for (const SeriesChange& c : series_changes(points, info.key.better, o.settings)) steps.insert(c.index);
    const std::size_t first = points.size() > static_cast<std::size_t>(o.last) ? points.size() - o.last : 0;
    std::vector<double> medians;
    for (std::size_t i = first; i < points.size(); ++i) medians.push_back(points[i].median);
    const SeriesKey& k = info.key;
    page += fmt::format("### {}\n{}  {}, {}\n\n", markdown_cell(series_label(k)), sparkline(medians),
                             k.unit.empty() ? "ratio" : k.unit,
                             k.better == Better::none ? "no direction" : fmt::format("{} is better", better_name(k.better)));
    page += "| commit | date | samples | median | min | max | step |\n|---|---|---:|---:|---:|---:|---|\n";
    for (std::size_t i = first; i < points.size(); ++i) {
      const CommitPoint& p = points[i];
      const auto [lo, hi] = std::minmax_element(p.samples.begin(), p.samples.end());
      std::string step;
      if (steps.count(i) != 0 && i > 0) {
        const double before = points[i - 1].median;
        const double change = before != 0.0 ? p.median / before - 1.0 : 0.0;
        step = fmt::format("**{} {:+.1f} %**", change_kind_name(classify_change(change, k.better)), 100.0 * change);
      }
      page += fmt::format("| {} | {} | {} | {:.6g} | {:.6g} | {:.6g} | {} |\n", p.commit.substr(0, 12), date_of(p.time),
                          p.samples.size(), p.median, *lo, *hi, step);
    }
    page += '\n';
    return Status{};
  });
  // Printed whole or not at all: a store error midway leaves no partial page.
  if (!visited) return fail_input(visited.error().message);
  std::cout << page;
  if (shown == 0) std::cout << fmt::format("no series match in {}\n", store->name());
  return exit_ok;
}

}  // namespace

void add_history_show_command(CLI::App& history, int& exit_code) {
  auto o = std::make_shared<ShowOptions>();
  CLI::App* show = history.add_subcommand("show", "The last commits of each series: a sparkline, every commit's spread, the steps");
  add_store_flags(show, o->store);
  add_series_filter_flags(show, o->filter);
  show->add_option("--last", o->last, "Commits shown per series")->check(CLI::Range(1, 100000))->capture_default_str();
  show->add_option("--window", o->settings.window, "Change points: points per window")->check(CLI::Range(2, 100000))->capture_default_str();
  show->add_option("--max-pvalue", o->settings.max_pvalue, "Change points: largest p-value")->check(CLI::Range(1e-12, 1.0))->capture_default_str();
  show->callback([o, &exit_code] { exit_code = run_show(*o); });
}

}  // namespace shatter::cli
