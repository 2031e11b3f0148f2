#include "harness/cli/command.h"
#include "harness/cli/history_subcommands.h"

namespace shatter::cli {

void add_history_command(CLI::App& app, int& exit_code) {
  CLI::App* history = app.add_subcommand(
      "history", "Results across commits: record runs, find where each series stepped, gate on it, draw the dashboard (docs/history.md)");
  history->require_subcommand(1);
  add_history_record_commands(*history, exit_code);
  add_history_changes_command(*history, exit_code);
  add_history_show_command(*history, exit_code);
  add_history_gate_commands(*history, exit_code);
  add_history_report_command(*history, exit_code);
}

}  // namespace shatter::cli
