// Hostile input, child processes: valgrind, gnuplot and the isolated cell start from an argument
// vector, so quotes, `$()`, spaces, newlines and non-ASCII bytes in paths are data, never commands.

#include "harness/process/child_process.h"
#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <string>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// A folder name holding every character a shell would read as syntax, plus a newline and non-ASCII.
const std::string kHostileName = "O'Brien \"quoted\" $(touch PWNED) `touch PWNED2` ; touch PWNED3 \n Zürich";

}  // namespace

TEST_CASE("no shell: a child's arguments arrive as written", "[hostile][no-shell]") {
  const fs::path dir = hostile_scratch("child_args");
  const fs::path target = dir / kHostileName;
  ChildOptions options;
  options.working_folder = dir;
  const Result<ChildExit> made = run_child({"mkdir", target.string()}, options);
  REQUIRE(made.ok());
  CHECK(made->exited);
  CHECK(made->code == 0);
  CHECK(fs::is_directory(target));
  // A relative output file is taken against this process's folder, not the child's.
  const Result<ChildExit> listed = run_child({"ls", "-1", "-b"}, ChildOptions{dir, dir / "ls.txt", {}});
  REQUIRE(listed.ok());
  CHECK_FALSE(file_bytes(dir / "ls.txt").empty());
  for (const char* planted : {"PWNED", "PWNED2", "PWNED3"}) {
    CHECK_FALSE(fs::exists(dir / planted));
    CHECK_FALSE(fs::exists(fs::current_path() / planted));
  }
  const Result<ChildExit> missing = run_child({"no-such-program-" + kHostileName});
  REQUIRE_FALSE(missing.ok());
  CHECK_THAT(missing.error().message, Catch::Contains("cannot run"));
  CHECK(program_runs("true", ""));
  CHECK_FALSE(program_runs("false", ""));
}

TEST_CASE("no shell: report draws into a folder whose path a shell would misread", "[hostile][no-shell][cli]") {
  const fs::path dir = hostile_scratch("report_path") / kHostileName;
  fs::create_directories(dir);
  const CliRun g = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                 "--repetitions", "1", "--frames", "2", "--no-cache", "--json",
                                 (dir / "grid 'one'.json").string()});
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
  const CliRun r = run_cli_argv({"report", (dir / "grid 'one'.json").string(), "--out", (dir / "rep $(x)").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(dir / "rep $(x)" / "report.md"));
  CHECK_FALSE(fs::exists(dir / "PWNED"));
}

TEST_CASE("no shell: instruction counting passes a hostile cache folder to valgrind as data",
          "[hostile][no-shell][cli][slow]") {
  if (!program_runs("valgrind", "--version")) FAIL("valgrind is not installed (scripts/install-deps installs it)");
  const fs::path dir = hostile_scratch("callgrind_path");
  const fs::path cache = dir / kHostileName;
  const CliRun run = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5",
                                   "--repetitions", "1", "--frames", "1", "--metric", "instructions", "--cache-dir",
                                   cache.string(), "--json", (dir / "g.json").string()},
                                  dir);
  INFO(run.err);
#if defined(__SANITIZE_ADDRESS__)
  // valgrind cannot run an AddressSanitizer build: the run fails with one line, and still nothing
  // planted in the path runs.
  CHECK(run.exit_code == 2);
  CHECK(line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains("callgrind"));
#else
  REQUIRE(run.exit_code == 0);
  CHECK(fs::is_directory(cache));  // the cache was written at exactly that path
  CHECK(fs::exists(dir / "g.json"));
#endif
  for (const char* planted : {"PWNED", "PWNED2", "PWNED3"}) CHECK_FALSE(fs::exists(dir / planted));
}
