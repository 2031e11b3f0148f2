// The history commands end to end on a git repository with commits at known times: record, show,
// changes (with filters and --since), gate (Markdown and JUnit), ack and import.

#include "tests/support/cli_runner.h"
#include "tests/support/history_fixtures.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

struct History {
  fs::path dir;
  std::string db;
  std::string repo;
  std::vector<std::string> shas;
};

/// 14 commits; each commit's run is the synthetic grid at scale 1 with 1 % noise, from commit
/// `step_at` on at scale `factor`.
History recorded_history(const std::string& name, int step_at, double factor) {
  History h;
  h.dir = history_scratch(name);
  h.db = (h.dir / "h.sqlite").string();
  h.repo = (h.dir / "repo").string();
  h.shas = make_commits(h.repo, 14);
  for (std::size_t i = 0; i < h.shas.size(); ++i) {
    const double scale = static_cast<int>(i) >= step_at ? factor : 1.0;
    const auto file = write_text(h.dir / ("run" + std::to_string(i) + ".json"),
                                 synthetic_grid_text(scale, 0.01, 100 + i, h.shas[i].substr(0, 12)));
    const CliRun r = run_cli_argv({"history", "record", file.string(), "--db", h.db, "--repo", h.repo});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("recorded run" + std::to_string(i) + ".json") == 0);
  }
  return h;
}

}  // namespace

TEST_CASE("history changes and show name the commit where a series stepped", "[history][cli]") {
  const History h = recorded_history("cli_changes", 8, 1.25);
  const CliRun c = run_cli_argv({"history", "changes", "--db", h.db, "--what", "stage physics", "--metric", "cpu_ms"});
  INFO(c.err);
  REQUIRE(c.exit_code == 0);
  CHECK(c.out.find("2 series, 2 with change points, 2 regression steps") == 0);
  // Both cells stepped at the ninth commit, +25 %.
  const std::string at = h.shas[8].substr(0, 12);
  CHECK(c.out.find("| " + at + " | 8 |") != std::string::npos);
  CHECK(c.out.find("+25.") != std::string::npos);
  CHECK(c.out.find("**regression**") != std::string::npos);
  // --since after the step: no step left in view.
  const CliRun since = run_cli_argv({"history", "changes", "--db", h.db, "--what", "stage physics", "--metric", "cpu_ms",
                                     "--since", h.shas[9].substr(0, 8)});
  REQUIRE(since.exit_code == 0);
  CHECK(since.out.find("2 series, 0 with change points") == 0);

  const CliRun show = run_cli_argv({"history", "show", "--db", h.db, "--subject", "10 x 25", "--what", "stage physics",
                                    "--metric", "cpu_ms", "--last", "10"});
  INFO(show.err);
  REQUIRE(show.exit_code == 0);
  CHECK(show.out.find("### synthetic · 10 x 25 plane-slice/plane-slice/von-mises · stage physics · cpu_ms") == 0);
  CHECK(show.out.find("▁") != std::string::npos);
  CHECK(show.out.find("| " + at + " |") != std::string::npos);
  CHECK(show.out.find("**regression +2") != std::string::npos);
  CHECK(line_count(show.out) == 2 + 1 + 2 + 10 + 1);  // heading, sparkline, blank, table head, 10 commits, blank
}

TEST_CASE("history gate fails on a recent step, passes once it is acknowledged", "[history][cli]") {
  const History h = recorded_history("cli_gate", 12, 1.15);  // the step landed two commits ago
  const fs::path md = h.dir / "comment.md", junit = h.dir / "gate.xml";
  const CliRun g = run_cli_argv({"history", "gate", "--commit", "HEAD", "--db", h.db, "--repo", h.repo, "--markdown",
                                 md.string(), "--junit", junit.string()});
  INFO(g.err);
  CHECK(g.exit_code == 1);
  CHECK(g.out.find("**shatterbench history gate: FAILED**") == 0);
  CHECK(g.err.find("shatterbench: regression: synthetic · 10 x 25") != std::string::npos);
  const std::string comment = slurp(md);
  CHECK(comment.find("### Regressions") != std::string::npos);
  CHECK(comment.find("<details>") != std::string::npos);
  CHECK(comment.find("stepped at " + h.shas[12].substr(0, 12)) != std::string::npos);
  const std::string xml = slurp(junit);
  CHECK(xml.find("<failure") != std::string::npos);
  CHECK(xml.find("type=\"regression\"") != std::string::npos);

  const CliRun ack = run_cli_argv({"history", "ack", "--commit", h.shas[12], "--db", h.db, "--case", "synthetic",
                                   "--note", "new physics settings"});
  INFO(ack.err);
  REQUIRE(ack.exit_code == 0);
  const CliRun again = run_cli_argv({"history", "gate", "--commit", "HEAD", "--db", h.db, "--repo", h.repo});
  INFO(again.err);
  CHECK(again.exit_code == 0);
  CHECK(again.out.find("**shatterbench history gate: passed**") == 0);
}

TEST_CASE("history gate passes a quiet history and fails a run over its budget", "[history][cli]") {
  const History h = recorded_history("cli_gate_quiet", 99, 1.0);
  const CliRun quiet = run_cli_argv({"history", "gate", "--commit", h.shas.back().substr(0, 10), "--db", h.db});
  INFO(quiet.err);
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.out.find("0 regressed, 0 improved and 0 failed run(s)") != std::string::npos);
  // One more commit whose run broke a 2 ms budget (the worst frame is 3 ms): a failed run.
  const std::string sha = git_in(h.repo, {"-c", "user.name=t", "-c", "user.email=t@example.org", "commit", "-q",
                                          "--allow-empty", "-m", "over budget"});
  const std::string head = git_in(h.repo, {"rev-parse", "HEAD"});
  const auto file = write_text(h.dir / "over.json", synthetic_grid_text(1.0, 0.01, 7, head.substr(0, 12), 2, 5, 2.0));
  REQUIRE(run_cli_argv({"history", "record", file.string(), "--db", h.db, "--repo", h.repo}).exit_code == 0);
  const CliRun over = run_cli_argv({"history", "gate", "--commit", "HEAD", "--db", h.db, "--repo", h.repo});
  CHECK(over.exit_code == 1);
  CHECK(over.err.find("run over.json (grid synthetic) failed its own checks") != std::string::npos);
}

TEST_CASE("history commands refuse bad input with one line", "[history][cli]") {
  const History h = recorded_history("cli_history_bad", 99, 1.0);
  const std::vector<std::vector<std::string>> bad = {
      {"history", "gate", "--commit", "deadbeefdead", "--db", h.db, "--repo", h.repo},
      {"history", "gate", "--commit", "HEAD", "--db", (h.dir / "missing.sqlite").string(), "--repo", h.repo},
      {"history", "gate", "--commit", "HEAD", "--db", h.db, "--repo", h.repo, "--alpha", "2"},
      {"history", "ack", "--commit", "HEAD", "--db", h.db, "--repo", h.repo, "--note", "x"},
      {"history", "changes", "--db", h.db, "--since", "--not-a-revision", "--repo", h.repo},
      {"history", "show", "--db", "postgresql://127.0.0.1:1/nothing"},
  };
  for (const auto& args : bad) {
    const CliRun r = run_cli_argv(args);
    INFO(args[1] << " " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.err) == 1);
  }
  CHECK_FALSE(fs::exists(h.dir / "missing.sqlite"));
}

TEST_CASE("history import takes a folder of artifacts, passing over other JSON", "[history][cli]") {
  const fs::path dir = history_scratch("cli_import");
  const std::string repo = (dir / "repo").string();
  const std::vector<std::string> shas = make_commits(repo, 2);
  fs::create_directories(dir / "artifacts" / "shard-1");
  write_text(dir / "artifacts" / "a.json", synthetic_grid_text(1.0, 0.01, 1, shas[0].substr(0, 12)));
  write_text(dir / "artifacts" / "shard-1" / "b.json", synthetic_grid_text(1.0, 0.01, 2, shas[1].substr(0, 12)));
  write_text(dir / "artifacts" / "gbench.json", R"({"context": {}, "benchmarks": []})");
  write_text(dir / "artifacts" / "notes.txt", "not json");
  const std::string db = (dir / "h.sqlite").string();
  const CliRun r = run_cli_argv({"history", "import", (dir / "artifacts").string(), "--db", db, "--repo", repo});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("recorded a.json") != std::string::npos);
  CHECK(r.out.find("recorded b.json") != std::string::npos);
  CHECK(r.err.find("passed over 1 JSON file(s)") != std::string::npos);
  const CliRun again = run_cli_argv({"history", "import", (dir / "artifacts").string(), "--db", db, "--repo", repo});
  CHECK(again.exit_code == 0);
  CHECK(again.out.find("already recorded a.json") != std::string::npos);
}

TEST_CASE("grid, accuracy and table --record put their runs in the store at the build's commit", "[history][cli]") {
  const fs::path dir = history_scratch("cli_record_flags");
  const std::string db = (dir / "h.sqlite").string();
  const fs::path source = SHATTER_SOURCE_DIR;  // the checkout whose git knows the build's commit
  const CliRun grid = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5", "--repetitions",
                                    "2", "--frames", "20", "--record", "--db", db}, source);
  INFO(grid.err);
  REQUIRE(grid.exit_code == 0);
  CHECK(grid.err.find("recorded building.json (grid building") != std::string::npos);
  const CliRun table = run_cli_argv({"table", "--mesh", "data/meshes/sphere.off", "--algo", "plane-slice", "--fragments", "5",
                                     "--repetitions", "2", "--json", (dir / "t.json").string(), "--record", "--db", db}, source);
  INFO(table.err);
  REQUIRE(table.exit_code == 0);
  CHECK(table.err.find("recorded t.json (table") != std::string::npos);
  const CliRun accuracy = run_cli_argv({"accuracy", "--case", "cantilever", "--family", "stress", "--model", "von-mises",
                                        "--repetitions", "1", "--record", "--db", db}, source);
  INFO(accuracy.err);
  REQUIRE(accuracy.exit_code == 0);
  CHECK(accuracy.err.find("recorded accuracy.json (accuracy") != std::string::npos);

  const CliRun show = run_cli_argv({"history", "show", "--db", db, "--metric", "time_ms", "--last", "1"});
  REQUIRE(show.exit_code == 0);
  CHECK(show.out.find("### building · 10 x 5 ") != std::string::npos);
  CHECK(show.out.find("### sphere.off · plane-slice 5 fragments · fracture · time_ms") != std::string::npos);
  CHECK(show.out.find("### cantilever · von-mises ") != std::string::npos);
  // The table JSON carries every repetition's time.
  const nlohmann::json t = nlohmann::json::parse(slurp(dir / "t.json"));
  CHECK(t["kind"] == "table");
  CHECK(t["rows"][0]["samples_ms"].size() == 2);

  const CliRun stray = run_cli_argv({"table", "--mesh", "data/meshes/sphere.off", "--db", db}, source);
  CHECK(stray.exit_code == 2);
  CHECK(stray.err.find("--db: only with --record") != std::string::npos);
}

TEST_CASE("history gate --baseline-branch judges a pull request against its target's commits only", "[history][cli]") {
  const fs::path dir = history_scratch("cli_baseline_branch");
  const std::string db = (dir / "h.sqlite").string(), repo = (dir / "repo").string();
  const std::vector<std::string> shas = make_commits(repo, 23);
  // main: 14 commits at scale 1; a feature branch: 8 commits 30 % slower; the pull request: scale 1.
  for (std::size_t i = 0; i < shas.size(); ++i) {
    const bool feature = i >= 14 && i < 22;
    const auto file = write_text(dir / ("r" + std::to_string(i) + ".json"),
                                 synthetic_grid_text(feature ? 1.3 : 1.0, 0.01, 300 + i, shas[i].substr(0, 12)));
    const std::string branch = i < 14 ? "main" : feature ? "feature" : "pr";
    REQUIRE(run_cli_argv({"history", "record", file.string(), "--db", db, "--repo", repo, "--branch", branch}).exit_code == 0);
  }
  const CliRun all = run_cli_argv({"history", "gate", "--commit", shas[22], "--db", db, "--metric", "cpu_ms"});
  INFO(all.err);
  CHECK(all.exit_code == 0);
  CHECK(all.out.find(", 0 improved and") == std::string::npos);  // against the feature's level it looks faster
  const CliRun main_only = run_cli_argv({"history", "gate", "--commit", shas[22], "--db", db, "--metric", "cpu_ms",
                                         "--baseline-branch", "main"});
  INFO(main_only.err);
  CHECK(main_only.exit_code == 0);
  CHECK(main_only.out.find("0 regressed, 0 improved and 0 failed run(s)") != std::string::npos);
}

TEST_CASE("history orders commits of one second by their ancestry", "[history][cli]") {
  // A rebased stack: 14 commits in one second, the newest twice as slow.
  const fs::path dir = history_scratch("cli_one_second");
  const std::string db = (dir / "h.sqlite").string(), repo = (dir / "repo").string();
  const std::vector<std::string> shas = make_commits(repo, 14, true);
  for (std::size_t i = 0; i < shas.size(); ++i) {
    const auto file = write_text(dir / ("r" + std::to_string(i) + ".json"),
                                 synthetic_grid_text(i == 13 ? 2.0 : 1.0, 0.01, 500 + i, shas[i].substr(0, 12)));
    REQUIRE(run_cli_argv({"history", "record", file.string(), "--db", db, "--repo", repo}).exit_code == 0);
  }
  const CliRun g = run_cli_argv({"history", "gate", "--commit", "HEAD", "--db", db, "--repo", repo});
  INFO(g.out);
  CHECK(g.exit_code == 1);
  CHECK(g.out.find("**regressed**") != std::string::npos);
}

TEST_CASE("history ack at a commit the series did not measure judges it from the next one", "[history][cli]") {
  const fs::path dir = history_scratch("cli_ack_unmeasured");
  const std::string db = (dir / "h.sqlite").string(), repo = (dir / "repo").string();
  const std::vector<std::string> shas = make_commits(repo, 16);
  // Commits 0..12 measured at scale 1, commit 13 not measured, 14 and 15 at scale 1.5.
  for (std::size_t i = 0; i < shas.size(); ++i) {
    if (i == 13) continue;
    const auto file = write_text(dir / ("r" + std::to_string(i) + ".json"),
                                 synthetic_grid_text(i > 13 ? 1.5 : 1.0, 0.01, 700 + i, shas[i].substr(0, 12)));
    REQUIRE(run_cli_argv({"history", "record", file.string(), "--db", db, "--repo", repo}).exit_code == 0);
  }
  CHECK(run_cli_argv({"history", "gate", "--commit", "HEAD", "--db", db, "--repo", repo}).exit_code == 1);
  // Commit 13 is recorded by a run of another case only; the ack there still moves the baseline on.
  const auto other = write_text(dir / "other.json", synthetic_grid_text(1.0, 0.01, 9, shas[13].substr(0, 12)));
  std::string text = slurp(other);
  text.replace(text.find("\"synthetic\""), 11, "\"elsewhere\"");
  write_text(other, text);
  REQUIRE(run_cli_argv({"history", "record", other.string(), "--db", db, "--repo", repo}).exit_code == 0);
  REQUIRE(run_cli_argv({"history", "ack", "--commit", shas[13], "--db", db, "--case", "synthetic", "--note", "expected"})
              .exit_code == 0);
  const CliRun after = run_cli_argv({"history", "gate", "--commit", "HEAD", "--db", db, "--repo", repo, "--case", "synthetic"});
  INFO(after.out);
  CHECK(after.exit_code == 0);
}

TEST_CASE("history refuses values beyond range and keeps secrets out of messages", "[history][cli]") {
  const fs::path dir = history_scratch("cli_hostile_values");
  const std::string db = (dir / "h.sqlite").string(), repo = (dir / "repo").string();
  const std::vector<std::string> shas = make_commits(repo, 1);
  std::string text = synthetic_grid_text(1.0, 0.01, 1, shas[0].substr(0, 12));
  // Every worst frame, the samples' included, at the edge of the doubles.
  std::size_t replaced = 0;
  for (std::size_t at = text.find("\"worst_frame_ms\""); at != std::string::npos; at = text.find("\"worst_frame_ms\"", at + 1)) {
    const std::size_t colon = text.find(':', at), end = text.find_first_of(",\n}", colon);
    text.replace(colon + 1, end - colon - 1, " 1.7e308");
    ++replaced;
  }
  REQUIRE(replaced > 2);
  const auto huge = write_text(dir / "huge.json", text);
  const CliRun r = run_cli_argv({"history", "record", huge.string(), "--db", db, "--repo", repo});
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("out of range") != std::string::npos);
  CHECK_FALSE(fs::exists(db));

  for (const std::string url : {"postgresql://bob:s3cr%ZZet@127.0.0.1:1/db", "postgresql://bob:s3cret@[::1/db",
                                "postgresql://bob:s3cret@127.0.0.1:1/db"}) {
    const CliRun p = run_cli_argv({"history", "show", "--db", url});
    INFO(p.err);
    CHECK(p.exit_code == 2);
    CHECK(line_count(p.err) == 1);
    CHECK(p.err.find("s3cr") == std::string::npos);
  }
  // A read-only command on an empty file: no store there, and none made.
  const auto empty = write_text(dir / "empty.sqlite", "");
  const CliRun e = run_cli_argv({"history", "show", "--db", empty.string()});
  CHECK(e.exit_code == 2);
  CHECK(e.err.find("no history store here") != std::string::npos);
  CHECK(fs::file_size(empty) == 0);
}

TEST_CASE("table --record keeps what ran: a refused row is left out and a repeated count pooled", "[history][cli]") {
  const fs::path dir = history_scratch("cli_table_rows");
  const std::string db = (dir / "h.sqlite").string();
  const fs::path source = SHATTER_SOURCE_DIR;
  // cgal-clip and plane-slice on the sphere, the count 5 twice: one series per fracturer, 4 samples each.
  const CliRun t = run_cli_argv({"table", "--mesh", "data/meshes/sphere.off", "--algo", "plane-slice", "--fragments", "5",
                                 "5", "--repetitions", "2", "--record", "--db", db}, source);
  INFO(t.err);
  REQUIRE(t.exit_code == 0);
  const CliRun s = run_cli_argv({"history", "show", "--db", db, "--metric", "time_ms"});
  CHECK(s.out.find("| 4 |") != std::string::npos);  // 2 repetitions x the count given twice
}
