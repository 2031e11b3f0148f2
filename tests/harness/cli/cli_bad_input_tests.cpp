// Every command refuses bad flags and bad files the same way: exit 2, one line on stderr naming the
// flag or the file, and no output left behind.

#include "tests/support/cli_runner.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using shatter::test::line_count;
using shatter::test::run_cli;

struct Bad {
  std::string args;   ///< the command line after `shatterbench`
  std::string names;  ///< what the one stderr line must name
};

}  // namespace

TEST_CASE("cli: every command refuses bad flags and files with exit 2, one line, no output", "[cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_bad_input";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string missing = (dir / "missing.off").string();
  const std::string garbage = (dir / "garbage.json").string();
  std::ofstream(garbage) << "{ not json";
  const std::string out = (dir / "out").string();
  if (!shatter::test::have_meshes()) return;  // two commands read elephant.off before they judge --algo
  const std::string elephant = (shatter::test::mesh_dir() / "elephant.off").string();
  const Bad cases[] = {
      {"list --bogus", "bogus"},
      {"nonsense-command", "nonsense-command"},
      {"fracture --mesh " + missing + " --algo plane-slice --fragments 5 --out " + out, "missing.off"},
      {"fracture --mesh " + garbage + " --algo plane-slice --fragments 5 --out " + out, "garbage.json"},
      {"fracture --mesh " + elephant + " --algo nope --fragments 5 --out " + out, "--algo"},
      {"stress --case " + garbage, "garbage.json"},
      {"stress --case cantilever --model nope", "--model"},
      {"table --mesh " + missing, "missing.off"},
      {"table --mesh " + elephant + " --algo nope", "--algo"},
      {"grid --case " + garbage + " --json " + out, "garbage.json"},
      {"grid --case building --threads 0 --json " + out, "--threads"},
      {"grid --case building --threads 65 --json " + out, "--threads"},
      {"grid --case building --threads two --json " + out, "--threads"},
      {"compare " + garbage + " " + garbage, "garbage.json"},
      {"merge " + garbage + " --out " + out, "garbage.json"},
      {"accuracy --case " + garbage + " --json " + out, "garbage.json"},
      {"report " + garbage + " --out " + out, "garbage.json"},
      {"stability --algo nope --json " + out, "--algo"},
  };
  for (const Bad& b : cases) {
    const auto r = run_cli(b.args);
    INFO(b.args << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(b.names) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  // Nothing but the two inputs is left in the folder (no temporary siblings either).
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  CHECK(files == 1);
  std::filesystem::remove_all(dir);
}
