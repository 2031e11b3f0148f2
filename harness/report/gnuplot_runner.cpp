#include "harness/report/gnuplot_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

extern char** environ;

namespace shatter {

std::string gnuplot_program() {
  if (const char* env = std::getenv("SHATTER_GNUPLOT"); env && *env) return env;
  return "gnuplot";
}

Status run_gnuplot(const std::filesystem::path& folder, const std::string& script) {
  const std::string program = gnuplot_program();
  const std::filesystem::path log = folder / (script + ".log");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {program, script};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    return Error{"cannot run " + program + ": install gnuplot-nox (scripts/install-deps) or set SHATTER_GNUPLOT"};
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return Error{"waiting for " + program + " failed"};
  std::string first_line;
  {
    std::ifstream in(log);
    std::getline(in, first_line);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
      return Error{"cannot run " + program + ": install gnuplot-nox (scripts/install-deps) or set SHATTER_GNUPLOT"};
    return Error{program + " failed on " + script + (first_line.empty() ? "" : ": " + first_line)};
  }
  std::error_code ec;
  if (std::filesystem::file_size(log, ec) == 0) std::filesystem::remove(log, ec);
  return {};
}

std::string gnuplot_quote(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace shatter
