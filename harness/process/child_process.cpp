#include "harness/process/child_process.h"

#include "harness/signals/interrupt_cleanup.h"

#include <cerrno>
#include <algorithm>
#include <cstring>

#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace shatter {
namespace fs = std::filesystem;

Result<ChildExit> run_child(const std::vector<std::string>& argv, const ChildOptions& options) {
  if (argv.empty() || argv[0].empty()) return Error{"cannot run a program without a name"};
  // Relative paths would be taken after the child's chdir: make them absolute first.
  const auto absolute = [](const fs::path& p) { return p.empty() ? p : fs::absolute(p); };
  const fs::path out = absolute(options.stdout_file);
  const fs::path err = absolute(options.stderr_file);
  std::error_code ec;
  if (!options.working_folder.empty() && !fs::is_directory(options.working_folder, ec))
    return Error{"cannot run " + argv[0] + ": the folder " + options.working_folder.string() + " does not exist"};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  if (!out.empty())
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!err.empty())
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!options.working_folder.empty())
    posix_spawn_file_actions_addchdir_np(&actions, fs::absolute(options.working_folder).c_str());
  std::vector<std::string> words = argv;
  std::vector<char*> pointers;
  for (std::string& w : words) pointers.push_back(w.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, words[0].c_str(), &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return Error{"cannot run " + argv[0] + ": " + std::strerror(spawned)};
  const KilledOnInterrupt killed_with_us(pid);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return Error{"waiting for " + argv[0] + " failed: " + std::strerror(errno)};
  }
  ChildExit result;
  result.exited = WIFEXITED(status);
  result.code = result.exited ? WEXITSTATUS(status) : (WIFSIGNALED(status) ? WTERMSIG(status) : -1);
  return result;
}

namespace {

/// Reads up to `max_bytes` of the anonymous file `fd` from its start, and closes it.
std::string read_back(int fd, std::size_t max_bytes) {
  std::string text;
  if (::lseek(fd, 0, SEEK_SET) == 0) {
    char buffer[4096];
    while (text.size() < max_bytes) {
      const ssize_t n = ::read(fd, buffer, std::min(sizeof buffer, max_bytes - text.size()));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      text.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return text;
}

}  // namespace

Result<ChildOutput> run_child_output(const std::vector<std::string>& argv, const fs::path& working_folder,
                                     std::size_t max_bytes) {
  if (argv.empty() || argv[0].empty()) return Error{"cannot run a program without a name"};
  const int out = ::memfd_create("child-stdout", MFD_CLOEXEC);
  const int err = ::memfd_create("child-stderr", MFD_CLOEXEC);
  if (out < 0 || err < 0) {
    if (out >= 0) ::close(out);
    if (err >= 0) ::close(err);
    return Error{"cannot run " + argv[0] + ": " + std::strerror(errno)};
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err, STDERR_FILENO);
  if (!working_folder.empty()) posix_spawn_file_actions_addchdir_np(&actions, fs::absolute(working_folder).c_str());
  std::vector<std::string> words = argv;
  std::vector<char*> pointers;
  for (std::string& w : words) pointers.push_back(w.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, words[0].c_str(), &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    ::close(out);
    ::close(err);
    return Error{"cannot run " + argv[0] + ": " + std::strerror(spawned)};
  }
  const KilledOnInterrupt killed_with_us(pid);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      ::close(out);
      ::close(err);
      return Error{"waiting for " + argv[0] + " failed: " + std::strerror(errno)};
    }
  }
  ChildOutput result;
  result.exit.exited = WIFEXITED(status);
  result.exit.code = result.exit.exited ? WEXITSTATUS(status) : (WIFSIGNALED(status) ? WTERMSIG(status) : -1);
  result.out = read_back(out, max_bytes);
  result.err = read_back(err, max_bytes);
  return result;
}

bool program_runs(const std::string& program, const std::string& argument) {
  std::vector<std::string> argv = {program};
  if (!argument.empty()) argv.push_back(argument);
  ChildOptions options;
  options.stdout_file = "/dev/null";
  options.stderr_file = "/dev/null";
  Result<ChildExit> e = run_child(argv, options);
  return e && e->exited && e->code == 0;
}

}  // namespace shatter
