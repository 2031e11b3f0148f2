// `shatterbench --version`: the project version, the commit built and the context fingerprint that the
// results of the same binary on the same machine carry.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <algorithm>
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
  const std::string& out = r.out;
  REQUIRE(out.rfind("shatterbench ", 0) == 0);
  const std::string version = out.substr(13, out.find('\n') - 13);
  CHECK(std::count(version.begin(), version.end(), '.') == 2);
  CHECK(version.find_first_not_of("0123456789.") == std::string::npos);
  CHECK(out.find("\ncommit ") != std::string::npos);
  CHECK(out.find("\nbuild ") != std::string::npos);
  const std::size_t at = out.find("\nfingerprint ");
  REQUIRE(at != std::string::npos);
  const std::string fingerprint = out.substr(at + 13, 16);
  CHECK(fingerprint.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(out.substr(at + 13 + 16) == "\n");
  // The same fingerprint as a grid run's results.
  const auto dir = std::filesystem::temp_directory_path() / "shatter_version_tests";
  std::filesystem::create_directories(dir);
  const auto json = dir / "grid.json";
  const auto g = run_cli("grid --case building --prefracture 10 --runtime 5 --repetitions 1 --frames 2 --json " +
                         json.string());
  REQUIRE(g.exit_code <= 1);
  CHECK(nlohmann::json::parse(slurp(json)).at("context").at("fingerprint") == fingerprint);
}
