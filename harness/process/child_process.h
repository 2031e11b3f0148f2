#pragma once
/// Running another program (valgrind, gnuplot) from an argument vector, never through a shell.
///
/// Every word reaches the program as written: paths with quotes, `$()`, spaces, newlines or non-ASCII
/// bytes are data, not syntax. The program is looked up on PATH when its name has no '/'.

#include "algorithms/core/result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shatter {

/// How a child process is started; empty paths mean "as this process has it" (stdin: /dev/null).
struct ChildOptions {
  std::filesystem::path working_folder;  ///< the child's working folder
  std::filesystem::path stdout_file;     ///< created or truncated; "/dev/null" to drop the output
  std::filesystem::path stderr_file;     ///< created or truncated
};

/// How a child process ended.
struct ChildExit {
  bool exited = false;  ///< ended by exit() (else by a signal)
  int code = -1;        ///< exit code when `exited`, else the signal number
};

/// Runs `argv` (argv[0] the program) to its end. Error when it cannot be started (a program that is
/// not installed included: "cannot run NAME: ..."), with the folder or files that could not be opened.
Result<ChildExit> run_child(const std::vector<std::string>& argv, const ChildOptions& options = {});

/// What a child wrote, as run_child_output() captured it.
struct ChildOutput {
  ChildExit exit;
  std::string out;  ///< its standard output, at most `max_bytes`
  std::string err;  ///< its standard error, at most `max_bytes`
};

/// Runs `argv` in `working_folder` (empty: this process's) with its standard output and error captured
/// in memory (anonymous files, no temporary names); at most `max_bytes` of each is kept.
Result<ChildOutput> run_child_output(const std::vector<std::string>& argv, const std::filesystem::path& working_folder,
                                     std::size_t max_bytes = 1 << 20);

/// True when `program` can be started and exits 0 with `argument` (e.g. "--version").
bool program_runs(const std::string& program, const std::string& argument);

}  // namespace shatter
