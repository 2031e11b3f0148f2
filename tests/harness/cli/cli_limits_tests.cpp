// The documented limits (docs/limits.md) from the command line: an input past one is refused with
// exit 2, one stderr line naming the file, key or flag and the limit, and nothing written. The inputs
// are tiny: headers announcing huge counts, sparse files, short flags.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using shatter::test::line_count;
using shatter::test::run_cli;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_limits_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

/// `count` comma-separated counts from `from` on.
std::string counts(int from, int count) {
  std::string out;
  for (int i = 0; i < count; ++i) {
    if (i > 0) out += ",";
    out += std::to_string(from + i);
  }
  return out;
}

struct Refusal {
  std::string args;                ///< after `shatterbench`
  std::vector<std::string> words;  ///< what the one stderr line must hold
};

void require_refused(const Refusal& b, const std::filesystem::path& out) {
  const auto r = run_cli(b.args);
  INFO(b.args << "\n" << r.err);
  CHECK(r.exit_code == 2);
  CHECK(line_count(r.err) == 1);
  CHECK(r.err.rfind("shatterbench: error: ", 0) == 0);
  for (const std::string& w : b.words) CHECK(r.err.find(w) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

}  // namespace

TEST_CASE("cli: mesh files past the limits are refused by their header or size", "[cli][limits]") {
  const auto dir = scratch("mesh");
  const auto out = dir / "out";
  const std::string faces = write(dir / "faces.off", "OFF\n4 4000000000 0\n0 0 0\n");
  const std::string vertices = write(dir / "vertices.off", "OFF\n4000000000 4 0\n0 0 0\n");
  const std::string large = write(dir / "large.off", "OFF\n4 4 0\n");
  std::filesystem::resize_file(large, (2ULL << 30) + 1);  // sparse: 2 GiB + 1 byte announced, none written
  const std::string fracture = " --algo plane-slice --fragments 4 --out " + out.string();
  const Refusal cases[] = {
      {"fracture --mesh " + faces + fracture,
       {faces + ":2: face count 4000000000 exceeds the limit of 10000000 triangles per mesh"}},
      {"fracture --mesh " + vertices + fracture,
       {vertices + ":2: vertex count 4000000000 exceeds the limit of 10000000 vertices per mesh"}},
      {"fracture --mesh " + large + fracture, {large, "larger than the limit of 2147483648 bytes per mesh file"}},
      {"table --mesh " + faces, {faces + ":2:", "limit of 10000000 triangles"}},
  };
  for (const Refusal& b : cases) require_refused(b, out);
  std::filesystem::remove_all(dir);
}

TEST_CASE("cli: grid refuses frames, repetitions, cells and pieces past the limits", "[cli][limits][grid]") {
  const auto dir = scratch("grid");
  const auto json = dir / "grid.json";
  const std::string out = " --no-cache --json " + json.string();
  const std::string cell = " --prefracture 10 --runtime 5";
  const Refusal cases[] = {
      {"grid --case building --frames 100001 --repetitions 1" + cell + out,
       {"--frames: must be <= 100000 (the limit per run), got 100001"}},
      {"grid --case building --repetitions 1001 --frames 1" + cell + out,
       {"--repetitions: must be <= 1000 (the limit per cell), got 1001"}},
      {"grid --case building --frames 1 --repetitions 1 --prefracture " + counts(1, 101) + " --runtime " +
           counts(1, 100) + out,
       {"--prefracture x --runtime: 101 x 100 = 10100 cells exceed the limit of 10000 cells per grid"}},
      {"grid --case building --frames 1 --repetitions 1 --prefracture 100000 --runtime 11" + out,
       {"cell 100000 x 11 can make 1100000 runtime pieces, which exceeds the limit of 1000000 pieces per run"}},
      {"grid --case building --frames 1 --repetitions 1 --prefracture 100001 --runtime 1" + out,
       {"--prefracture: counts must be <= 100000 (the fragment limit), got 100001"}},
      {"grid --case building --frames 100000 --repetitions 81" + cell + out,
       {"100000 x 81 x 1 = 8100000 frames recorded exceed the limit of 8000000"}},
      {"table --mesh " + write(dir / "t.off", "OFF\n0 0 0\n") + " --repetitions 1001", {"--repetitions", "1000"}},
  };
  for (const Refusal& b : cases) require_refused(b, json);
  std::filesystem::remove_all(dir);
}

TEST_CASE("cli: case files past the limits are refused naming the key", "[cli][limits][grid]") {
  const auto dir = scratch("case");
  const auto json = dir / "grid.json";
  const std::string out = " --frames 1 --repetitions 1 --no-cache --json " + json.string();
  const std::string frames = write(dir / "frames.json", R"({"mesh": {"box": {"size": [1, 1, 1]}}, "frames": 1000000})");
  const std::string sphere =
      write(dir / "sphere.json", R"({"mesh": {"sphere": {"radius": 1, "segments": 4096, "rings": 4096}}})");
  const std::string large = write(dir / "large.json", R"({"mesh": {"box": {"size": [1, 1, 1]}}})");
  std::filesystem::resize_file(large, 64u << 20);  // sparse
  const Refusal cases[] = {
      {"grid --case " + frames + out, {frames + ": frames: must be <= 100000, got 1000000"}},
      {"grid --case " + sphere + out, {sphere + ": mesh.sphere: segments x rings = 4096 x 4096", "limit of 10000000"}},
      {"stress --case " + sphere, {sphere + ": mesh.sphere:", "limit of 10000000 triangles"}},
      {"grid --case " + large + out, {large + ": larger than the limit of 16777216 bytes per case file"}},
  };
  for (const Refusal& b : cases) require_refused(b, json);
  std::filesystem::remove_all(dir);
}
