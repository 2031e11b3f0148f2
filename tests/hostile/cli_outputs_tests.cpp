// Hostile input, outputs through the command line: every command's outputs obey harness/output/
// (refused targets, a folder of the user's, a killed run, concurrent runs, standard output that fails).

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "harness/output/atomic_file.h"
#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include <sys/stat.h>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

void require_refused(const CliRun& run, const std::string& mentions) {
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains(mentions));
}

/// A small grid results file (building, one cell, one repetition, two frames) at `path`.
void small_grid(const fs::path& path, int prefracture = 10) {
  const CliRun g = run_cli_argv({"grid", "--case", "building", "--prefracture", std::to_string(prefracture),
                                 "--runtime", "5", "--repetitions", "1", "--frames", "2", "--no-cache", "--json",
                                 path.string()});
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
}

/// Starts `shatterbench args...` without waiting; its output is dropped.
pid_t start_cli(const std::vector<std::string>& args) { return spawn_cli(args, {}, "/dev/null", "/dev/null"); }

}  // namespace

TEST_CASE("cli outputs: targets that are not regular files or that two outputs share are refused",
          "[hostile][outputs][cli]") {
  const fs::path dir = hostile_scratch("cli_targets");
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0644) == 0);
  const std::string grid = (dir / "grid.json").string();
  small_grid(grid);
  const std::string tiny[] = {"--case", "building", "--prefracture", "10", "--runtime", "5", "--repetitions", "1",
                              "--frames", "1", "--no-cache"};
  const auto grid_with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"grid"};
    args.insert(args.end(), std::begin(tiny), std::end(tiny));
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli_argv(args);
  };
  require_refused(grid_with({"--json", "/dev/null"}), "not a regular file");
  require_refused(grid_with({"--json", (dir / "fifo").string()}), "not a regular file");
  require_refused(grid_with({"--junit", dir.string()}), "not a regular file");
  require_refused(grid_with({"--json", (dir / "x.json").string(), "--junit", (dir / "x.json").string()}), "--junit");
  require_refused(grid_with({"--json", (dir / "x.json").string(), "--junit", (dir / "x.csv").string()}), "CSV");
  require_refused(run_cli_argv({"merge", grid, "--out", (dir / "m.csv").string()}), "CSV");
  require_refused(run_cli_argv({"compare", grid, grid, "--markdown", (dir / "c").string(), "--junit",
                                (dir / "sub" / ".." / "c").string()}),
                  "--markdown");
  require_refused(run_cli_argv({"accuracy", "--case", "cantilever", "--family", "stress", "--slabs", "8", "--json",
                                (dir / "fifo").string()}),
                  "not a regular file");
  require_refused(run_cli_argv({"merge", grid, "--out", "/dev/zero"}), "not a regular file");
  struct stat st {};
  REQUIRE(::stat((dir / "fifo").c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(names_in(dir) == std::set<std::string>{"fifo", "grid.json", "grid.csv"});
}

TEST_CASE("cli outputs: a file of the user's, an input, or one file through two links is never replaced",
          "[hostile][outputs][cli]") {
  const fs::path dir = hostile_scratch("cli_user_files");
  const std::string tiny[] = {"--case", "building", "--prefracture", "10", "--runtime", "5", "--repetitions", "1",
                              "--frames", "1", "--no-cache"};
  const auto grid_with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"grid"};
    args.insert(args.end(), std::begin(tiny), std::end(tiny));
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli_argv(args);
  };
  // The CSV beside a --json target is an output too: a user's CSV there is refused, named.
  put_file(dir / "mydata.csv", "x,y\n1,2\n");
  require_refused(grid_with({"--json", (dir / "mydata.json").string()}), "mydata.csv");
  CHECK(file_bytes(dir / "mydata.csv") == "x,y\n1,2\n");
  CHECK_FALSE(fs::exists(dir / "mydata.json"));
  // A file of the user's named as an output, of any command.
  put_file(dir / "thesis.txt", "chapter one\n");
  require_refused(grid_with({"--json", (dir / "thesis.txt").string()}), "not a file shatterbench wrote");
  require_refused(grid_with({"--junit", (dir / "thesis.txt").string()}), "not a file shatterbench wrote");
  small_grid(dir / "s0.json");
  small_grid(dir / "s1.json", 20);
  require_refused(run_cli_argv({"merge", (dir / "s0.json").string(), (dir / "s1.json").string(), "--out",
                                (dir / "thesis.txt").string()}),
                  "not a file shatterbench wrote");
  require_refused(run_cli_argv({"accuracy", "--case", "cantilever", "--family", "stress", "--slabs", "8", "--json",
                                (dir / "thesis.txt").string()}),
                  "not a file shatterbench wrote");
  require_refused(run_cli_argv({"compare", (dir / "s0.json").string(), (dir / "s0.json").string(), "--markdown",
                                (dir / "thesis.txt").string()}),
                  "not a file shatterbench wrote");
  CHECK(file_bytes(dir / "thesis.txt") == "chapter one\n");
  // An output that is one of the command's inputs.
  const std::string s0 = file_bytes(dir / "s0.json");
  require_refused(run_cli_argv({"merge", (dir / "s0.json").string(), (dir / "s1.json").string(), "--out",
                                (dir / "s0.json").string()}),
                  "is also an input");
  require_refused(run_cli_argv({"compare", (dir / "s0.json").string(), (dir / "s1.json").string(), "--markdown",
                                (dir / "s1.json").string()}),
                  "is also an input");
  CHECK(file_bytes(dir / "s0.json") == s0);
  // Two outputs that are one new file through links (the links dangle until the file is written).
  fs::create_symlink(dir / "one.json", dir / "a.json");
  fs::create_symlink(dir / "one.json", dir / "b.xml");
  require_refused(grid_with({"--json", (dir / "a.json").string(), "--junit", (dir / "b.xml").string()}), "--junit");
  CHECK_FALSE(fs::exists(dir / "one.json"));
  // The command's own earlier output is replaced.
  const CliRun again = grid_with({"--json", (dir / "s0.json").string(), "--junit", (dir / "s0.xml").string()});
  CHECK(again.exit_code == 0);
  const CliRun third = grid_with({"--json", (dir / "s0.json").string(), "--junit", (dir / "s0.xml").string()});
  CHECK(third.exit_code == 0);
}

TEST_CASE("cli outputs: a folder of the user's is never replaced by report or fracture, their own is",
          "[hostile][outputs][cli]") {
  const fs::path dir = hostile_scratch("cli_folders");
  const fs::path grid = dir / "grid.json";
  small_grid(grid);
  const fs::path mesh = dir / "cube.off";
  REQUIRE(write_off(make_box({1, 1, 1}), mesh).ok());
  fs::create_directory(dir / "mine");
  put_file(dir / "mine" / "notes.txt", "mine");
  require_refused(run_cli_argv({"report", grid.string(), "--out", (dir / "mine").string()}), "did not write");
  require_refused(run_cli_argv({"fracture", "--mesh", mesh.string(), "--fragments", "3", "--out",
                                (dir / "mine").string()}),
                  "did not write");
  CHECK(names_in(dir / "mine") == std::set<std::string>{"notes.txt"});

  // A relative --out (gnuplot runs in the staging folder) works, and a second run replaces the first.
  for (int run = 0; run < 2; ++run) {
    const CliRun r = run_cli_argv({"report", "grid.json", "--out", "rep"}, dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(fs::exists(dir / "rep" / "report.md"));
    CHECK(fs::exists(dir / "rep" / kOutputMarker));
  }
  const CliRun five = run_cli_argv({"fracture", "--mesh", mesh.string(), "--fragments", "5", "--out", "frag"}, dir);
  REQUIRE(five.exit_code == 0);
  const CliRun two = run_cli_argv({"fracture", "--mesh", mesh.string(), "--fragments", "2", "--out", "frag"}, dir);
  REQUIRE(two.exit_code == 0);
  const auto count = nlohmann::json::parse(two.out)["fragments"].get<std::size_t>();
  // The new fragments, the glTF file of all of them, their summary and the marker: no old fragment stays.
  CHECK(names_in(dir / "frag").size() == count + 3);
  CHECK(fs::exists(dir / "frag" / "fracture.json"));
  CHECK(fs::exists(dir / "frag" / "fragments.glb"));
  CHECK(partials_in(dir) == 0);
}

TEST_CASE("cli outputs: kill -9 during fracture --out leaves the old folder, the next run leaves nothing partial",
          "[hostile][outputs][cli][kill]") {
  const fs::path dir = hostile_scratch("cli_kill");
  const fs::path mesh = dir / "cube.off";
  REQUIRE(write_off(make_box({1, 1, 1}), mesh).ok());
  const fs::path out = dir / "out";
  REQUIRE(run_cli_argv({"fracture", "--mesh", mesh.string(), "--fragments", "4", "--out", out.string()}).exit_code == 0);
  const std::set<std::string> old_names = names_in(out);
  const pid_t pid = start_cli({"fracture", "--mesh", mesh.string(), "--fragments", "5000", "--out", out.string()});
  REQUIRE(pid > 0);
  const bool caught = wait_until([&] {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(".partial-") != std::string::npos &&
          fs::exists(e.path() / "fragment_100.obj"))
        return true;
    return false;
  });
  kill_and_reap(pid);
  REQUIRE(caught);
  CHECK(names_in(out) == old_names);
  CHECK(partials_in(dir) == 1);
  REQUIRE(run_cli_argv({"fracture", "--mesh", mesh.string(), "--fragments", "3", "--out", out.string()}).exit_code == 0);
  CHECK(partials_in(dir) == 0);
}

TEST_CASE("cli outputs: concurrent merges to one output leave a JSON and CSV of one run", "[hostile][outputs][cli]") {
  const fs::path dir = hostile_scratch("cli_concurrent");
  small_grid(dir / "ten.json", 10);
  small_grid(dir / "twenty.json", 20);
  const fs::path out = dir / "merged.json";
  for (int trial = 0; trial < 8; ++trial) {
    const pid_t a = start_cli({"merge", (dir / "ten.json").string(), "--out", out.string()});
    const pid_t b = start_cli({"merge", (dir / "twenty.json").string(), "--out", out.string()});
    for (const pid_t pid : {a, b}) {
      int status = 0;
      ::waitpid(pid, &status, 0);
      REQUIRE(WIFEXITED(status));
      REQUIRE(WEXITSTATUS(status) == 0);
    }
    const int json_prefracture = nlohmann::json::parse(file_bytes(out))["cells"][0]["prefracture"].get<int>();
    const std::string csv = file_bytes(dir / "merged.csv");
    const std::string row = csv.substr(csv.find('\n') + 1);
    CHECK(row.rfind(std::to_string(json_prefracture) + ",", 0) == 0);
    CHECK(partials_in(dir) == 0);
  }
}

TEST_CASE("cli outputs: standard output that cannot be written is exit 2", "[hostile][outputs][cli]") {
  const fs::path dir = hostile_scratch("cli_stdout");
  const std::string err = (dir / "err").string();
  for (const std::string& command :
       {std::string("list"), std::string("--version"), std::string("stress --case cantilever --json")}) {
    const std::string line = std::string(SHATTER_CLI) + " " + command + " >/dev/full 2>" + err;
    const int status = std::system(line.c_str());
    INFO(command << ": " << file_bytes(err));
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(line_count(file_bytes(err)) == 1);
    CHECK_THAT(file_bytes(err), Catch::Contains("standard output"));
  }
}
