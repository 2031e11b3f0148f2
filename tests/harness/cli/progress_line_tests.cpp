// accuracy and stability show one rewritten progress line when stderr is a terminal (a pseudo-terminal
// here) and none when it is a file, as grid does.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace {

/// Runs shatterbench with `args` on a pseudo-terminal (stdout and stderr both) and returns what it
/// wrote there and its exit code.
std::pair<std::string, int> run_on_terminal(const std::vector<std::string>& args) {
  std::vector<std::string> words = {SHATTER_CLI};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  REQUIRE(pid > 0);
  std::string out;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(master, buffer, sizeof buffer);
    if (n <= 0) break;  // EIO once the child has closed the terminal
    out.append(buffer, static_cast<std::size_t>(n));
  }
  close(master);
  int status = 0;
  waitpid(pid, &status, 0);
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

}  // namespace

TEST_CASE("progress: accuracy rewrites one line per step on a terminal, none into a file", "[cli][progress]") {
  const std::vector<std::string> args = {"accuracy", "--case", "cantilever", "column", "--family", "stress",
                                         "--repetitions", "1", "--slabs", "8", "--resolution", "8"};
  const auto [terminal, code] = run_on_terminal(args);
  CHECK(code == 0);
  CHECK_THAT(terminal, Catch::Contains("\raccuracy: step 1 of 2 (cantilever, stress)") &&
                           Catch::Contains("\raccuracy: step 2 of 2 (column, stress)"));
  const shatter::test::CliRun file = shatter::test::run_cli_argv(args);
  CHECK(file.exit_code == 0);
  CHECK_THAT(file.err, !Catch::Contains("accuracy: step"));
}

TEST_CASE("progress: stability rewrites its line on a terminal and logs a line per result elsewhere",
          "[cli][progress]") {
  const std::vector<std::string> args = {"stability", "--algo", "plane-slice", "--model", "none", "--quick",
                                         "--hazard", "inverted-orientation", "--hazard", "pinched-vertex"};
  const auto [terminal, code] = run_on_terminal(args);
  CHECK(code == 0);
  CHECK_THAT(terminal, Catch::Contains("\rstability: step 1 (inverted-orientation / plane-slice: ") &&
                           Catch::Contains("\rstability: step 2 (pinched-vertex / plane-slice: "));
  const shatter::test::CliRun file = shatter::test::run_cli_argv(args);
  CHECK(file.exit_code == 0);
  CHECK_THAT(file.err, Catch::Contains("stability: inverted-orientation / plane-slice: ") &&
                           !Catch::Contains("\r"));
}
