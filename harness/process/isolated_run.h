#pragma once
/// Running one piece of work in a forked child, so that a crash or a hang of the algorithm under test
/// becomes a verdict instead of the end of the run (docs/stability.md, "Isolation").

#include <functional>
#include <string>

namespace shatter {

/// How an isolated run ended.
struct IsolatedRun {
  enum class End { finished, crashed, timed_out };
  End end = End::crashed;
  std::string output;   ///< what the child returned (finished only)
  std::string detail;   ///< "signal 11 (Segmentation fault)", "exit 1", ... (crashed only)
  double time_ms = 0.0; ///< wall time until the child ended or was killed, ms
};

/// Forks, runs `work` in the child and hands its string back through a pipe. The child is killed
/// (SIGKILL) after `time_limit_s` seconds. The child never returns into the caller's code: it leaves
/// with _exit, so no destructor or atexit handler of the parent runs twice.
IsolatedRun run_isolated(const std::function<std::string()>& work, double time_limit_s);

}  // namespace shatter
