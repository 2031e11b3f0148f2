// `history report --out DIR`: the dashboard page written whole from the store, its change points the
// ones `history changes` finds; hostile text from the store stays data; bad input is one line, exit 2,
// and nothing written.

#include "harness/history/dashboard/dashboard_html.h"
#include "tests/support/cli_runner.h"
#include "tests/support/history_fixtures.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

const std::string kHostile = "</script><script>alert(1)</script>";

struct Recorded {
  fs::path dir;
  std::string db;
  std::string repo;
  std::vector<std::string> shas;
};

/// 12 commits of the synthetic grid, +25 % from the eighth on; the case named `case_name`, recorded on
/// branch `branch`.
Recorded recorded(const std::string& name, const std::string& case_name, const std::string& branch) {
  Recorded h;
  h.dir = history_scratch(name);
  h.db = (h.dir / "h.sqlite").string();
  h.repo = (h.dir / "repo").string();
  h.shas = make_commits(h.repo, 12);
  for (std::size_t i = 0; i < h.shas.size(); ++i) {
    nlohmann::json results = nlohmann::json::parse(
        synthetic_grid_text(i >= 7 ? 1.25 : 1.0, 0.01, 300 + i, h.shas[i].substr(0, 12)));
    results["case"]["name"] = case_name;
    const auto file = write_text(h.dir / ("run" + std::to_string(i) + ".json"), results.dump(2));
    const CliRun r = run_cli_argv({"history", "record", file.string(), "--db", h.db, "--repo", h.repo, "--branch", branch});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
  }
  return h;
}

/// The data element of a dashboard page, parsed.
nlohmann::json page_data(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"" + std::string(kDashboardDataElementId) + "\">";
  const std::size_t begin = page.find(open);
  REQUIRE(begin != std::string::npos);
  const std::size_t end = page.find("</script>", begin);
  return nlohmann::json::parse(page.substr(begin + open.size(), end - begin - open.size()));
}

}  // namespace

TEST_CASE("history report writes dashboard.html with the change points history changes finds", "[history][cli][dashboard]") {
  const Recorded h = recorded("cli_dashboard", kHostile, "feature/<b>bold</b>");
  const fs::path out = h.dir / "dashboard";
  const CliRun r = run_cli_argv({"history", "report", "--db", h.db, "--out", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("dashboard: ") == 0);
  const std::string page = slurp(out / "dashboard.html");
  REQUIRE(page.size() > 1000);
  CHECK(page.find("</html>\n") == page.size() - 8);  // written whole
  CHECK(page.find(kHostile) == std::string::npos);
  CHECK(page.find("<b>bold</b>") == std::string::npos);
  const nlohmann::json data = page_data(page);
  REQUIRE(data["commits"].size() == 12);
  CHECK(data["commits"][0]["branch"] == "feature/<b>bold</b>");
  REQUIRE(!data["series"].empty());
  CHECK(data["series"][0]["case"] == kHostile);
  std::size_t changes = 0;
  for (const nlohmann::json& s : data["series"]) changes += s["changes"].size();
  // `history changes` over the same store names as many change points.
  const CliRun c = run_cli_argv({"history", "changes", "--db", h.db});
  REQUIRE(c.exit_code == 0);
  std::size_t rows = 0;
  for (std::size_t at = c.out.find("\n| "); at != std::string::npos; at = c.out.find("\n| ", at + 1)) ++rows;
  CHECK(rows == changes + 1);  // the table's head row too
  CHECK(changes > 0);
  const std::smatch printed = [&] {
    std::smatch m;
    std::regex_search(r.out, m, std::regex("(\\d+) series over 12 commits, (\\d+) change points"));
    return m;
  }();
  REQUIRE(printed.size() == 3);
  CHECK(std::stoul(printed[1]) == data["series"].size());
  CHECK(std::stoul(printed[2]) == changes);

  // The filters of `history changes` narrow the page; a second report replaces the first.
  const CliRun only = run_cli_argv({"history", "report", "--db", h.db, "--out", out.string(), "--what", "stage physics",
                                    "--metric", "cpu_ms", "--since", h.shas[2].substr(0, 10)});
  INFO(only.err);
  REQUIRE(only.exit_code == 0);
  const nlohmann::json narrowed = page_data(slurp(out / "dashboard.html"));
  CHECK(narrowed["series"].size() == 2);
  CHECK(narrowed["commits"].size() == 10);
  for (const nlohmann::json& s : narrowed["series"]) CHECK(s["what"] == "stage physics");

  // A filter that matches nothing still writes a page, which says so.
  const CliRun none = run_cli_argv({"history", "report", "--db", h.db, "--out", out.string(), "--case", "nothing"});
  REQUIRE(none.exit_code == 0);
  CHECK(none.out.find("dashboard: 0 series over 0 commits") == 0);
  CHECK(page_data(slurp(out / "dashboard.html"))["series"].empty());
}

TEST_CASE("history report refuses bad input with one line and writes nothing", "[history][cli][dashboard]") {
  const Recorded h = recorded("cli_dashboard_bad", "synthetic", "main");
  const fs::path user = h.dir / "user-folder";
  fs::create_directories(user);
  write_text(user / "notes.txt", "mine");
  const fs::path fresh = h.dir / "fresh";
  const std::vector<std::vector<std::string>> bad = {
      {"history", "report", "--db", h.db, "--out", user.string()},                                // a folder of other files
      {"history", "report", "--db", (h.dir / "missing.sqlite").string(), "--out", fresh.string()},  // no store
      {"history", "report", "--db", h.db, "--out", fresh.string(), "--since", "deadbeefdead", "--repo", h.repo},
      {"history", "report", "--db", h.db, "--out", fresh.string(), "--window", "1"},
      {"history", "report", "--db", h.db, "--out", h.dir.string()},                              // holds the store
      {"history", "report", "--db", h.db},                                                       // no --out
      {"history", "report", "--db", "postgresql://127.0.0.1:1/nothing", "--out", fresh.string()},
  };
  for (const auto& args : bad) {
    const CliRun r = run_cli_argv(args);
    INFO(args.back() << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.out.empty());
  }
  CHECK_FALSE(fs::exists(fresh));
  CHECK_FALSE(fs::exists(h.dir / "missing.sqlite"));
  CHECK(slurp(user / "notes.txt") == "mine");
  CHECK(std::distance(fs::directory_iterator(user), fs::directory_iterator()) == 1);
  CHECK(fs::exists(h.db));
}
