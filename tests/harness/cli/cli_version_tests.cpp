// `shatterbench --version`: the project version, the commit built and the context fingerprint that the
// results of the same binary on the same machine carry.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <string>

namespace {

using shatter::test::run_cli;
using shatter::test::slurp;

}  // namespace

TEST_CASE("cli: --version names the version, the commit and the results' fingerprint", "[cli][version]") {
  const auto r = run_cli("--version");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  std::smatch m;
  REQUIRE(std::regex_search(r.out, m, std::regex(R"(^shatterbench \d+\.\d+\.\d+\n)")));
  REQUIRE(std::regex_search(r.out, m, std::regex(R"(\ncommit \S+\n)")));
  REQUIRE(std::regex_search(r.out, m, std::regex(R"(\nfingerprint ([0-9a-f]{16})\n)")));
  const std::string fingerprint = m[1];
  // The same fingerprint as a grid run's results.
  const auto dir = std::filesystem::temp_directory_path() / "shatter_version_tests";
  std::filesystem::create_directories(dir);
  const auto json = dir / "grid.json";
  const auto g = run_cli("grid --case building --prefracture 10 --runtime 5 --repetitions 1 --frames 2 --json " +
                         json.string());
  REQUIRE(g.exit_code <= 1);
  CHECK(nlohmann::json::parse(slurp(json)).at("context").at("fingerprint") == fingerprint);
}
