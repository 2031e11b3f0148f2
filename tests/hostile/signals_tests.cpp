// Interrupts (harness/signals/interrupt_cleanup.h): SIGTERM or SIGINT to a command that runs work in
// children ends those children with it, leaves no temporary and no partial output, and the command
// ends with the signal's conventional status.

#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// The pids whose parent is `parent` (from /proc/PID/stat).
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(e.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const std::size_t close = line.rfind(')');  // the command name may hold spaces and parentheses
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    pid_t ppid = 0;
    rest >> state >> ppid;
    if (ppid == parent && state != 'Z') out.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return out;
}

bool alive(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

/// Starts the CLI with `args` in `dir`, waits until it has a child, sends `sig`, and checks the ending.
void interrupt_with_a_child(const std::vector<std::string>& args, const fs::path& dir, int sig) {
  const pid_t pid = spawn_cli(args, dir, dir / "stdout.txt", dir / "stderr.txt");
  REQUIRE(pid > 0);
  std::vector<pid_t> children;
  const bool started = wait_until([&] {
    children = children_of(pid);
    return !children.empty();
  });
  if (!started) kill_and_reap(pid);
  REQUIRE(started);
  REQUIRE(::kill(pid, sig) == 0);
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  CHECK(WIFSIGNALED(status));
  if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == sig);
  for (const pid_t child : children) {
    INFO("child " << child);
    CHECK(wait_until([&] { return !alive(child); }, std::chrono::milliseconds(5000)));
  }
  CHECK(partials_in(dir) == 0);
}

}  // namespace

TEST_CASE("signals: SIGTERM to grid --timeout ends the cell's child and writes nothing", "[hostile][signals][cli]") {
  const fs::path dir = hostile_scratch("sigterm_grid");
  interrupt_with_a_child({"grid", "--case", "building", "--prefracture", "100", "--runtime", "25", "--repetitions",
                          "20", "--frames", "300", "--no-cache", "--timeout", "600", "--json", "g.json"},
                         dir, SIGTERM);
  CHECK_FALSE(fs::exists(dir / "g.json"));
  CHECK_FALSE(fs::exists(dir / "g.csv"));
}

TEST_CASE("signals: SIGINT to stability ends its child and writes nothing", "[hostile][signals][cli]") {
  const fs::path dir = hostile_scratch("sigint_stability");
  interrupt_with_a_child({"stability", "--algo", "all", "--model", "all", "--json", "s.json"}, dir, SIGINT);
  CHECK_FALSE(fs::exists(dir / "s.json"));
}
