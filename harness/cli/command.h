#pragma once
/// The CLI's commands. Each command file adds one subcommand to the app and sets the exit code when
/// it runs: 0 ok, 1 a gate failed, 2 bad input or usage (with one line on stderr).

#include "algorithms/registry/registries.h"
#include "harness/plugins/plugin_loader.h"

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace shatter::cli {

/// Exit codes of the CLI (DESIGN.md section 8; README "The command line"). exit_internal_error is a
/// defect of shatterbench itself or memory exhausted (an exception no command turned into an answer),
/// with one line on stderr; every fault of a plugin's code is its algorithm's failed result instead.
enum ExitCode : int { exit_ok = 0, exit_gate_failed = 1, exit_bad_input = 2, exit_internal_error = 3 };

/// Prints "shatterbench: error: <message>" on stderr (one line) and returns exit_bad_input.
int fail_input(std::string_view message);

/// Prints "shatterbench: check failed: <message>" on stderr (one line) and returns exit_gate_failed:
/// the command's own check found its result invalid, so nothing of it is reported as an answer.
int fail_check(std::string_view message);

/// An algorithm's error, `context` (e.g. the mesh) before it: fail_check for a fault of the algorithm's
/// code (ErrorCause::algorithm_fault: it failed on an accepted input, exit 1), fail_input otherwise.
int fail_algorithm(std::string_view context, const Error& error);

/// Prints "shatterbench: check failed: <subject>: <check>" on stderr for every entry of `failed` (one
/// line each; "<subject>: " left out when `subject` is empty) and returns the number of lines printed.
int print_failed_checks(std::string_view subject, const std::vector<std::string>& failed);

/// Adds `--cap-uv-scale METRES` (metres per UV unit on cut faces of an attributed solid; a length in
/// the case-file range) to `cmd`, stored in `out` (0 when absent: the case's or the default scale).
void add_cap_uv_scale_option(CLI::App* cmd, double& out);

/// Commands that create plugins take the registries they look them up in (kept by reference: they
/// must outlive the app's parse).
/// `shatterbench list`: each name a plugin added (a key of `origins`) names the plugin's file.
void add_list_command(CLI::App& app, int& exit_code, const Registries& registries, const PluginOrigins& origins);
/// `shatterbench fracture`.
void add_fracture_command(CLI::App& app, int& exit_code, const Registries& registries);
/// `shatterbench stress`.
void add_stress_command(CLI::App& app, int& exit_code, const Registries& registries);
/// `shatterbench grid`.
void add_grid_command(CLI::App& app, int& exit_code, const Registries& registries);
/// `shatterbench compare`.
void add_compare_command(CLI::App& app, int& exit_code);
/// `shatterbench merge`.
void add_merge_command(CLI::App& app, int& exit_code);
/// `shatterbench history` (its subcommand `changes`).
void add_history_command(CLI::App& app, int& exit_code);
/// `shatterbench table`.
void add_table_command(CLI::App& app, int& exit_code, const Registries& registries);
/// `shatterbench accuracy`.
void add_accuracy_command(CLI::App& app, int& exit_code, const Registries& registries);
/// `shatterbench report`.
void add_report_command(CLI::App& app, int& exit_code);
/// `shatterbench stability`.
void add_stability_command(CLI::App& app, int& exit_code, const Registries& registries);

}  // namespace shatter::cli
