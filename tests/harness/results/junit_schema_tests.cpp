// JUnit output of `grid --junit` and `compare --junit` against the schema of the Ant JUnit report
// format (tests/fixtures/junit/junit.xsd), checked by xmllint (libxml2-utils), and the fields CI
// systems show: the test's time is the time the cell took, its frame figures are properties, the
// failure message is not repeated as the failure's text, the suite has a timestamp, a host name and
// the run's commit and fingerprint.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <string>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("shatter_junit_schema_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

/// xmllint's verdict on `xml` against the JUnit schema: its exit code (0 valid) and what it said.
std::pair<int, std::string> validate(const fs::path& xml) {
  const fs::path xmllint = "/usr/bin/xmllint";
  REQUIRE(fs::exists(xmllint));  // scripts/install-deps installs libxml2-utils
  const fs::path schema = fs::path(SHATTER_SOURCE_DIR) / "tests" / "fixtures" / "junit" / "junit.xsd";
  REQUIRE(fs::exists(schema));
  std::vector<std::string> words = {xmllint.string(), "--noout", "--schema", schema.string(), xml.string()};
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const fs::path err = xml.string() + ".lint";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  REQUIRE(spawned == 0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::slurp(err)};
}

}  // namespace

TEST_CASE("junit: grid and compare write JUnit valid against the schema, with times, properties and one message",
          "[junit]") {
  const fs::path dir = scratch();
  const fs::path a = dir / "a.json";
  const fs::path xml = dir / "grid.xml";
  // Budget 0.001 ms: every cell fails its budget.
  const test::CliRun run = test::run_cli_argv({"grid", "--case", "building", "--prefracture", "10,20", "--runtime",
                                               "5", "--repetitions", "2", "--frames", "3", "--no-cache",
                                               "--budget-ms", "0.001", "--json", a.string(), "--junit", xml.string()});
  REQUIRE(run.exit_code == 1);
  const auto [code, said] = validate(xml);
  INFO(said);
  CHECK(code == 0);
  const std::string text = test::slurp(xml);
  CHECK_THAT(text, Catch::Contains("<testsuite name=\"shatterbench.grid.building\" package=\"shatterbench.grid\""));
  CHECK(std::regex_search(text, std::regex("timestamp=\"[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}\"")));
  CHECK(std::regex_search(text, std::regex("<property name=\"fingerprint\" value=\"[0-9a-f]{16}\"/>")));
  CHECK_THAT(text, Catch::Contains("<property name=\"commit\"") && Catch::Contains("<property name=\"budget_ms\" value=\"0.001\"/>"));
  // The worst frame is a property; the test's time is the cell's wall time, more than its 6 frames.
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex("<property name=\"cell 10 x 5: worst_frame_ms\" value=\"([0-9.]+)\"/>")));
  const double worst_ms = std::stod(m[1].str());
  REQUIRE(std::regex_search(text, m, std::regex("<testcase name=\"cell 10 x 5\" classname=\"shatterbench.grid.building\" time=\"([0-9.]+)\"")));
  CHECK(std::stod(m[1].str()) > worst_ms / 1000.0);
  // The message once, no failure text repeating it.
  CHECK(std::regex_search(text, std::regex("<failure message=\"worst frame [0-9.]+ ms &gt; budget 0.001 ms\" type=\"budget\"/>")));

  // compare --junit: a second run against the first.
  const fs::path b = dir / "b.json";
  REQUIRE(test::run_cli_argv({"grid", "--case", "building", "--prefracture", "10,20", "--runtime", "5",
                              "--repetitions", "2", "--frames", "3", "--no-cache", "--json", b.string()})
              .exit_code == 0);
  const fs::path compared = dir / "compare.xml";
  const test::CliRun cmp = test::run_cli_argv({"compare", a.string(), b.string(), "--junit", compared.string()});
  CHECK((cmp.exit_code == 0 || cmp.exit_code == 1));
  const auto [compare_code, compare_said] = validate(compared);
  INFO(compare_said);
  CHECK(compare_code == 0);

  // The schema refuses what it should: a test case without its time.
  const fs::path broken = dir / "broken.xml";
  {
    std::string bad = text;
    const std::size_t at = bad.find(" time=\"", bad.find("<testcase "));
    REQUIRE(at != std::string::npos);
    bad.erase(at, bad.find('"', at + 7) - at + 1);
    std::ofstream(broken) << bad;
  }
  CHECK(validate(broken).first != 0);
  fs::remove_all(dir);
}
