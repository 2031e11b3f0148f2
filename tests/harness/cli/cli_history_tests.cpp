// `history changes --csv`: the change points of a plain commit,value series, as a table naming the
// commits; a malformed series or flag is one line and exit 2.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / "shatter_cli_history_tests";
  fs::create_directories(dir);
  return dir;
}

fs::path write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("cli history changes: the TigerBeetle series as commit,value lines gives Otava's change points",
          "[cli][history]") {
  std::ifstream in(SHATTER_SOURCE_DIR "/tests/fixtures/otava-tigerbeetle-series.json");
  REQUIRE(in.good());
  const std::vector<double> series = nlohmann::json::parse(in).at("series").get<std::vector<double>>();
  std::string csv = "commit,value\n";
  for (std::size_t i = 0; i < series.size(); ++i) csv += "sha" + std::to_string(i) + "," + std::to_string(series[i]) + "\n";
  const fs::path file = write(scratch() / "tigerbeetle.csv", csv);
  const CliRun run = run_cli_argv({"history", "changes", "--csv", file.string(), "--max-pvalue", "1e-5"});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Catch::Contains("365 points, 5 change points"));
  for (const int index : {71, 95, 131, 192, 212})
    CHECK_THAT(run.out, Catch::Contains("| sha" + std::to_string(index) + " | " + std::to_string(index) + " |"));
}

TEST_CASE("cli history changes: a malformed series or flag is one line, exit 2", "[cli][history]") {
  const fs::path dir = scratch();
  const struct {
    std::string text;
    std::string says;
  } bad[] = {
      {"a,1\nb,x\n", ":2: the value 'x' is not a finite number"},
      {"a,1\nb,2,3\n", ":2: expected two fields"},
      {"a,1\n,2\n", ":2: the commit is empty"},
      {"a,1\nb,nan\n", "not a finite number"},
      {"\n\n", "holds no point"},
  };
  for (const auto& [text, says] : bad) {
    INFO(text);
    const fs::path file = write(dir / "bad.csv", text);
    const CliRun run = run_cli_argv({"history", "changes", "--csv", file.string()});
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(line_count(run.err) == 1);
    CHECK_THAT(run.err, Catch::Contains(says));
  }
  const fs::path good = write(dir / "good.csv", "a,1\nb,2\n");
  for (const std::vector<std::string>& flags : {std::vector<std::string>{"--window", "1"}, {"--max-pvalue", "0"},
                                                {"--min-magnitude", "-1"}}) {
    std::vector<std::string> args = {"history", "changes", "--csv", good.string()};
    args.insert(args.end(), flags.begin(), flags.end());
    const CliRun run = run_cli_argv(args);
    CHECK(run.exit_code == 2);
    CHECK(line_count(run.err) == 1);
  }
  CHECK(run_cli_argv({"history", "changes", "--csv", (dir / "missing.csv").string()}).exit_code == 2);
}
