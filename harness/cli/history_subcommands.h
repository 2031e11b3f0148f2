#pragma once
/// The subcommands of `shatterbench history` (docs/cli.md), each added by its own file.

#include <CLI/CLI.hpp>

namespace shatter::cli {

/// `history record` and `history import`.
void add_history_record_commands(CLI::App& history, int& exit_code);
/// `history changes`.
void add_history_changes_command(CLI::App& history, int& exit_code);
/// `history show`.
void add_history_show_command(CLI::App& history, int& exit_code);
/// `history gate` and `history ack`.
void add_history_gate_commands(CLI::App& history, int& exit_code);
/// `history report` (the dashboard page).
void add_history_report_command(CLI::App& history, int& exit_code);

}  // namespace shatter::cli
