// `fracture --out` carries the input's textures with the fragments (harness/results/fragment_writer.h):
// a texture file an OBJ's material names is copied into DIR/textures and both the MTL and the glTF
// name the copy; an image embedded in a glTF binary is written out for the MTL; a named texture that
// cannot be read leaves no output.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <unistd.h>

using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// A fresh folder of this test process for `name`.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shatter_texture_tests_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void put_file(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

std::string file_bytes(const fs::path& p) { return slurp(p); }

/// A unit cube OBJ with texture coordinates whose one material names `texture` through box.mtl.
void put_textured_box(const fs::path& dir, const std::string& texture) {
  put_file(dir / "box.obj",
           "mtllib box.mtl\n"
           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl painted\n"
           "f 1/1 4/4 3/3 2/2\nf 5/1 6/2 7/3 8/4\nf 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n");
  put_file(dir / "box.mtl", "newmtl painted\nKd 1 1 1\nmap_Kd " + texture + "\n");
}

}  // namespace

TEST_CASE("fracture --out copies a texture file the input's material names and names the copy",
          "[cli][assets][textures]") {
  const fs::path dir = scratch("texture_copy");
  fs::create_directories(dir / "in" / "maps");
  put_textured_box(dir / "in", "maps/checker.png");
  const std::string image = "\x89PNG\r\n\x1a\n" + std::string(300, 'c');
  put_file(dir / "in" / "maps" / "checker.png", image);
  const CliRun run = run_cli_argv({"fracture", "--mesh", (dir / "in" / "box.obj").string(), "--algo", "plane-slice",
                                   "--fragments", "3", "--out", (dir / "out").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(file_bytes(dir / "out" / "textures" / "checker.png") == image);
  CHECK_THAT(file_bytes(dir / "out" / "fragments.mtl"), Catch::Contains("map_Kd textures/checker.png\n"));
  const std::string glb = file_bytes(dir / "out" / "fragments.glb");
  CHECK(glb.find("\"uri\":\"textures/checker.png\"") != std::string::npos);
  CHECK(glb.find("maps/checker.png") == std::string::npos);
}

TEST_CASE("fracture --out writes an embedded texture out for the MTL and keeps it in the glTF binary",
          "[cli][assets][textures]") {
  const fs::path dir = scratch("texture_embedded");
  const fs::path asset = fs::path(SHATTER_SOURCE_DIR) / "data" / "assets" / "BoxTextured.glb";
  REQUIRE(fs::is_regular_file(asset));
  const CliRun run = run_cli_argv({"fracture", "--mesh", asset.string(), "--algo", "plane-slice", "--fragments", "3",
                                   "--out", (dir / "out").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  REQUIRE(fs::is_directory(dir / "out" / "textures"));
  int images = 0;
  for (const auto& e : fs::directory_iterator(dir / "out" / "textures")) {
    const std::string bytes = file_bytes(e.path());
    CHECK(bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0);  // the PNG as the input embedded it
    CHECK(file_bytes(asset).find(bytes) != std::string::npos);
    CHECK_THAT(file_bytes(dir / "out" / "fragments.mtl"),
               Catch::Contains("map_Kd textures/" + e.path().filename().string() + "\n"));
    ++images;
  }
  CHECK(images == 1);
  CHECK(file_bytes(dir / "out" / "fragments.glb").find("\"uri\"") == std::string::npos);  // still embedded
}

TEST_CASE("fracture --out refuses a texture it cannot copy and writes nothing", "[cli][assets][textures]") {
  const fs::path dir = scratch("texture_missing");
  fs::create_directories(dir / "in");
  put_textured_box(dir / "in", "absent.png");
  const CliRun run = run_cli_argv({"fracture", "--mesh", (dir / "in" / "box.obj").string(), "--algo", "plane-slice",
                                   "--fragments", "3", "--out", (dir / "out").string()});
  CHECK(run.exit_code == 2);
  CHECK(line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains("painted") && Catch::Contains("absent.png"));
  CHECK_FALSE(fs::exists(dir / "out"));
}
