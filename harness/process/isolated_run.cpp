#include "harness/process/isolated_run.h"

#include "harness/signals/interrupt_cleanup.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace shatter {
namespace {

void write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

IsolatedRun run_isolated(const std::function<std::string()>& work, double time_limit_s) {
  IsolatedRun run;
  int fds[2];
  if (::pipe(fds) != 0) {
    run.detail = std::string("pipe failed: ") + std::strerror(errno);
    return run;
  }
  std::fflush(nullptr);  // buffered output must not be printed twice
  const auto start = std::chrono::steady_clock::now();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    run.detail = std::string("fork failed: ") + std::strerror(errno);
    return run;
  }
  if (pid == 0) {
    ::close(fds[0]);
    // A crash must end the child, not run the parent's handlers (a test framework's, for example);
    // an interrupt ends it as the default says, and so does its parent's end, however it comes.
    for (const int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL, SIGTRAP}) std::signal(sig, SIG_DFL);
    reset_interrupt_cleanup_in_child();
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(3);  // the parent ended before the request took effect
    int code = 0;
    try {
      write_all(fds[1], work());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "shatterbench: exception in an isolated run: %s\n", e.what());
      code = 3;
    } catch (...) {
      code = 3;
    }
    ::close(fds[1]);
    ::_exit(code);
  }
  ::close(fds[1]);
  const KilledOnInterrupt killed_with_us(pid);
  const auto elapsed_ms = [&] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  bool timed_out = false;
  char buffer[4096];
  for (;;) {
    const double left_ms = time_limit_s * 1000.0 - elapsed_ms();
    if (left_ms <= 0.0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min(left_ms, 1000.0)) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child closed its end (finished or died)
    run.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  run.time_ms = elapsed_ms();
  if (timed_out) {
    run.end = IsolatedRun::End::timed_out;
    run.output.clear();
  } else if (WIFSIGNALED(status)) {
    run.detail = "signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
    run.detail = "exit " + std::to_string(WEXITSTATUS(status));
  } else {
    run.end = IsolatedRun::End::finished;
  }
  if (run.end != IsolatedRun::End::finished) run.output.clear();
  return run;
}

}  // namespace shatter
