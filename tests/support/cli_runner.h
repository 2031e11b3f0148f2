#pragma once
/// Runs the shatterbench binary from tests and captures what it printed.

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

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

/// The run that ended with wait status `status`, its output read from (and then removed with) `out`
/// and `err`.
inline CliRun collect_run(int status, const std::filesystem::path& out, const std::filesystem::path& err) {
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(out);
  run.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

/// Runs `shatterbench <args>` (args are passed to the shell as written).
inline CliRun run_cli(const std::string& args) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() / "shatter_cli_tests";
  std::filesystem::create_directories(dir);
  const auto out = dir / ("out" + std::to_string(::getpid()) + "_" + std::to_string(counter));
  const auto err = dir / ("err" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string cmd = std::string(SHATTER_CLI) + " " + args + " >" + out.string() + " 2>" + err.string();
  return collect_run(std::system(cmd.c_str()), out, err);
}

/// Starts `shatterbench` with `args` as its argument vector (no shell: any byte but NUL passes through
/// as written), standard output and error into the files named, `cwd` as the working folder when not
/// empty. Returns the child's pid, -1 when it could not start; the caller waits for it.
inline pid_t spawn_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                       const std::filesystem::path& out, const std::filesystem::path& err) {
  std::vector<std::string> words = {SHATTER_CLI};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? pid : -1;
}

/// Runs `shatterbench` with `args` as its argument vector (spawn_cli) and waits for it.
inline CliRun run_cli_argv(const std::vector<std::string>& args, const std::filesystem::path& cwd = {}) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() / "shatter_cli_tests";
  std::filesystem::create_directories(dir);
  const std::string tag = std::to_string(::getpid()) + "_argv" + std::to_string(counter++);
  const auto out = std::filesystem::absolute(dir / ("out" + tag));
  const auto err = std::filesystem::absolute(dir / ("err" + tag));
  const pid_t pid = spawn_cli(args, cwd, out, err);
  if (pid < 0) return {};
  int status = 0;
  ::waitpid(pid, &status, 0);
  return collect_run(status, out, err);
}

/// Number of lines in `s` (a final line without newline counts).
inline int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  if (!s.empty() && s.back() != '\n') ++n;
  return n;
}

}  // namespace shatter::test
