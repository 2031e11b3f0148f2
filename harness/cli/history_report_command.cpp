#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/cli/history_subcommands.h"
#include "harness/history/dashboard/dashboard_html.h"
#include "harness/history/dashboard/dashboard_writer.h"
#include "harness/history/dashboard_data.h"
#include "harness/history/store/postgres_connection.h"
#include "harness/output/output_targets.h"

#include <fmt/core.h>

#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace shatter::cli {
namespace {

struct DashboardOptions {
  StoreFlags store;
  SeriesFilter filter;
  std::string since;
  std::string repo;
  std::string out;
  HistoryGateSettings gate;
};

int run_dashboard(const DashboardOptions& o) {
  // The store file is an input: a folder output that holds it is refused (the swap would remove it).
  std::vector<std::filesystem::path> inputs;
  const std::string location = history_store_location(o.store.db);
  if (!is_postgres_url(location)) inputs.emplace_back(location);
  if (Status s = check_outputs({{"--out", o.out, true}}, baseline_folders(), inputs); !s)
    return fail_input(s.error().message);
  Result<HistoryStore> store = open_store(o.store, false);
  if (!store) return fail_input(store.error().message);
  const Result<std::int64_t> since = since_time(*store, o.since, o.repo);
  if (!since) return fail_input(since.error().message);
  Result<nlohmann::json> data = dashboard_data(*store, o.filter, o.gate, *since);
  if (!data) return fail_input(data.error().message);
  std::size_t changes = 0, regressed = 0;
  for (const nlohmann::json& s : (*data)["series"]) {
    changes += s["changes"].size();
    if (s.contains("newest") && s["newest"]["verdict"] == "regressed") ++regressed;
  }
  if (Status s = write_dashboard(dashboard_html(*data), o.out); !s) return fail_input(s.error().message);
  std::cout << fmt::format("dashboard: {} series over {} commits, {} change points, {} open regressions ({}) -> {}/{}\n",
                           (*data)["series"].size(), (*data)["commits"].size(), changes, regressed, store->name(), o.out,
                           kDashboardFileName);
  return exit_ok;
}

}  // namespace

void add_history_report_command(CLI::App& history, int& exit_code) {
  auto o = std::make_shared<DashboardOptions>();
  CLI::App* cmd = history.add_subcommand(
      "report", "Write DIR/dashboard.html: every series' trend over the commits, its change points, open regressions "
      "first (docs/dashboard.md)");
  cmd->add_option("--out", o->out, "Dashboard folder (replaced as a whole when the page is complete)")->required();
  add_store_flags(cmd, o->store);
  add_series_filter_flags(cmd, o->filter);
  cmd->add_option("--since", o->since, "Only commits at or after this one (a recorded sha prefix or a git revision)");
  cmd->add_option("--repo", o->repo, "The git repository that resolves --since (default: the working folder)");
  ChangePointSettings& cp = o->gate.change_points;
  cmd->add_option("--window", cp.window, "Change points: points per window of the split pass")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  cmd->add_option("--max-pvalue", cp.max_pvalue, "Change points: largest t-test p-value")
      ->check(CLI::Range(1e-12, 1.0))
      ->capture_default_str();
  cmd->add_option("--min-magnitude", cp.min_magnitude, "Change points: smallest relative change")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->callback([o, &exit_code] { exit_code = run_dashboard(*o); });
}

}  // namespace shatter::cli
