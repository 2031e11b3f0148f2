#include "harness/cli/command.h"
#include "harness/output/output_targets.h"
#include "harness/report/report_inputs.h"
#include "harness/report/report_writer.h"

#include <fmt/core.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace shatter::cli {
namespace {

struct ReportOptions {
  std::vector<std::string> files;
  std::string out;
  std::vector<int> cell;  // pre-fracture, runtime; empty: the largest cell
};

int run_report(const ReportOptions& o) {
  const std::vector<std::filesystem::path> results(o.files.begin(), o.files.end());
  if (Status s = check_outputs({{"--out", o.out, true}}, baseline_folders(), results); !s)
    return fail_input(s.error().message);
  Result<ReportInputs> inputs = read_report_inputs(o.files);
  if (!inputs) return fail_input(inputs.error().message);
  ChosenCell cell;
  if (!o.cell.empty()) cell = std::pair(o.cell[0], o.cell[1]);
  if (Status s = write_report(*inputs, o.out, cell); !s) return fail_input(s.error().message);
  std::cout << fmt::format("report: {} grid, {} accuracy, {} stability and {} table file(s), {} fragments folder(s) "
                           "-> {}/report.md, {}/report.html\n",
                           inputs->grids.size(), inputs->accuracies.size(), inputs->stabilities.size(),
                           inputs->tables.size(), inputs->fragments.size(), o.out, o.out);
  return exit_ok;
}

}  // namespace

void add_report_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "report", "Draw a report (heat map, stage bars, time against error, tables; report.md and report.html) from grid, "
      "accuracy, stability and table results");
  cmd->add_option("results", o->files, "Results files: grid, accuracy, stability and table JSON (their --json), and fragments folders "
                  "(fracture --out, table --out) for the 3D views")
      ->required();
  cmd->add_option("--out", o->out, "Report folder (replaced as a whole when the report is complete)")->required();
  cmd->add_option("--cell", o->cell, "Grid cell of the stage bars: PREFRACTURE,RUNTIME (default: the largest)")
      ->delimiter(',')
      ->expected(2);
  cmd->callback([o, &exit_code] { exit_code = run_report(*o); });
}

}  // namespace shatter::cli
