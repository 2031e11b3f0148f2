// The OFF/OBJ lexical layer (mesh_text.h) and read_off against an independent reader: the C library's
// strtod over whitespace-split tokens, on every real mesh and on hand-written tricky text.
#include "algorithms/core/mesh_text.h"

#include "algorithms/core/mesh_io.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace shatter {
namespace {

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / ("shatter_mesh_text_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// A plain-triangle OFF without comments read by std::istream and strtod: nullopt when the file has
/// something this simple reader does not handle (then the case is not compared).
std::optional<Mesh> reference_off(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string keyword;
  long long nv = 0, nf = 0, ne = 0;
  if (!(in >> keyword >> nv >> nf >> ne) || keyword != "OFF") return std::nullopt;
  Mesh mesh;
  for (long long v = 0; v < nv; ++v) {
    std::string x, y, z;
    if (!(in >> x >> y >> z)) return std::nullopt;
    mesh.add_vertex({std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr), std::strtod(z.c_str(), nullptr)});
  }
  for (long long f = 0; f < nf; ++f) {
    int n = 0, a = 0, b = 0, c = 0;
    if (!(in >> n) || n != 3 || !(in >> a >> b >> c)) return std::nullopt;
    mesh.add_triangle(a, b, c, FaceTag::surface);
  }
  return mesh;
}

std::string read_error(const std::filesystem::path& path) {
  const Result<Mesh> mesh = read_mesh(path);
  return mesh ? std::string("no error") : mesh.error().message;
}

}  // namespace

TEST_CASE("mesh_text: read_off gives exactly what strtod reads, on every real triangle mesh", "[mesh_io]") {
  if (!test::have_meshes()) return;
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::mesh_dir())) {
    if (entry.path().extension() != ".off") continue;
    const std::optional<Mesh> reference = reference_off(entry.path());
    if (!reference) continue;
    const Result<Mesh> mesh = read_off(entry.path());
    INFO(entry.path().filename().string());
    REQUIRE(mesh.ok());
    CHECK(mesh->vertices == reference->vertices);  // bit for bit
    CHECK(mesh->triangles == reference->triangles);
    ++compared;
  }
  CHECK(compared > 20);
}

TEST_CASE("mesh_text: line ends, blanks, comments and exponents read the same whatever the layout", "[mesh_io]") {
  const std::string plain =
      "OFF\n4 4 0\n0 0 0\n1.5e0 0 0\n0 2.5E-1 0\n0 0 1e+0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const Result<Mesh> expected = read_off(write_temp("plain.off", plain));
  REQUIRE(expected.ok());
  CHECK(expected->vertices[2] == Vec3(0, 0.25, 0));
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"crlf.off", "OFF\r\n4 4 0\r\n0 0 0\r\n1.5e0 0 0\r\n0 2.5E-1 0\r\n0 0 1e+0\r\n3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n"},
           {"cr.off", "OFF\r4 4 0\r0 0 0\r1.5e0 0 0\r0 2.5E-1 0\r0 0 1e+0\r3 0 2 1\r3 0 1 3\r3 0 3 2\r3 1 2 3"},
           {"blanks.off", "OFF\t\n 4\t4 0 \n\v0 0 0\f\n+1.5 0 0\n0\t0.25 0#c\n0 0 1 # x 1,5 nan\n#\n3 0 2 1\n3\t0 1 3\n3 0 3 2\n3 1 2 3"},
       }) {
    const Result<Mesh> mesh = read_off(write_temp(name, text));
    INFO(name);
    REQUIRE(mesh.ok());
    CHECK(mesh->vertices == expected->vertices);
    CHECK(mesh->triangles == expected->triangles);
  }
}

TEST_CASE("mesh_text: '1,5' and 'nan' are errors naming file and line, with any line ends", "[mesh_io]") {
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    const std::string head = "OFF" + end + "3 1 0" + end + "0 0 0" + end;
    const std::filesystem::path comma = write_temp("comma.off", head + "1,5 0 0" + end + "0 1 0" + end + "3 0 1 2" + end);
    CHECK_THAT(read_error(comma), StartsWith(comma.string() + ":4: vertex 1: non-numeric token '1,5'"));
    const std::filesystem::path nan = write_temp("nan.off", head + "1 0 0" + end + "0 nan 0" + end + "3 0 1 2" + end);
    CHECK_THAT(read_error(nan), StartsWith(nan.string() + ":5: vertex 2: ") && Contains("'nan'"));
    const std::filesystem::path obj = write_temp("nan.obj", "v 0 0 0" + end + "# c" + end + "v 1 0 1e999" + end);
    CHECK_THAT(read_error(obj), StartsWith(obj.string() + ":3: ") && Contains("outside the range of a double"));
  }
}

TEST_CASE("mesh_text: TokenLines splits on the C locale's blanks and counts every line end", "[mesh_io]") {
  TokenLines lines("a\tb\v c\f#d e\r\n\r\n  \rx#\ny");
  REQUIRE(lines.next());
  CHECK(lines.line() == 1);
  CHECK(lines.tokens() == std::vector<std::string_view>{"a", "b", "c"});
  REQUIRE(lines.next());
  CHECK(lines.line() == 4);
  CHECK(lines.tokens() == std::vector<std::string_view>{"x"});
  REQUIRE(lines.next());
  CHECK(lines.line() == 5);
  CHECK(lines.tokens() == std::vector<std::string_view>{"y"});
  CHECK_FALSE(lines.next());
}

}  // namespace shatter
