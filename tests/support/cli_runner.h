#pragma once
/// Runs the shatterbench binary from tests and captures what it printed.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace shatter::test {

/// What one CLI run gave.
struct CliRun {
  int exit_code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `shatterbench <args>` (args are passed to the shell as written).
inline CliRun run_cli(const std::string& args) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() / "shatter_cli_tests";
  std::filesystem::create_directories(dir);
  const auto out = dir / ("out" + std::to_string(::getpid()) + "_" + std::to_string(counter));
  const auto err = dir / ("err" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string cmd = std::string(SHATTER_CLI) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(out);
  run.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

/// Number of lines in `s` (a final line without newline counts).
inline int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  if (!s.empty() && s.back() != '\n') ++n;
  return n;
}

}  // namespace shatter::test
