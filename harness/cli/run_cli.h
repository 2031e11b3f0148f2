#pragma once
/// The whole command line as a library call: a program registers its own plugins beside the built-ins
/// and gets every command (list, table, grid, accuracy, stability, ...) for them.
///
///   shatter::Registries registries;
///   shatter::register_all(registries);
///   my_fracturers::register_shards(registries.fracturers);
///   return shatter::run_cli(argc, argv, registries);

#include "algorithms/registry/registries.h"

namespace shatter {

/// Parses `argv` (argv[0] the program, argv[1] the command) and runs the command with the plugins of
/// `registries`. Returns the exit code of DESIGN.md section 8: 0 ok, 1 a gate or check failed, 2 bad
/// input or usage (one line on stderr), 3 an internal error. Writes to stdout and stderr.
int run_cli(int argc, char** argv, const Registries& registries);

}  // namespace shatter
