#include "algorithms/assets/read_asset.h"
#include "algorithms/core/mesh_validation.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

/// assimp-testmodels' glTF 2.0 folder (scripts/install-deps installs it; a test fails without it).
const fs::path kGltf = "/usr/share/assimp/models/glTF2";

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shatter_read_asset_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// The error of reading `path`, checked to be one line that starts with the path.
std::string one_line_error(const fs::path& path, const MeshReadLimits& limits = {}) {
  const Result<Mesh> mesh = read_asset(path, limits);
  REQUIRE_FALSE(mesh.ok());
  const std::string& message = mesh.error().message;
  INFO(message);
  CHECK_THAT(message, StartsWith(path.string() + ": "));
  CHECK(message.find('\n') == std::string::npos);
  CHECK(message.size() > path.string().size() + 2);
  return message;
}

}  // namespace

TEST_CASE("read_asset: the textured glTF box is a closed solid with UVs and its embedded PNG", "[assets]") {
  // The file's own figures: 24 vertices (4 per face), 36 indices, TEXCOORD_0 within [0, 6] x [0, 1],
  // material 0 "Texture" with image 0, a PNG in the binary chunk.
  const fs::path box = kGltf / "BoxTextured-glTF-Binary" / "BoxTextured.glb";
  REQUIRE(fs::exists(box));
  Result<Mesh> mesh = read_asset(box);
  REQUIRE(mesh.ok());
  // A cube with a UV seam on every edge: 4 corners per face, 6 faces; 2 triangles per face.
  CHECK(mesh->vertices.size() == 24);
  REQUIRE(mesh->triangles.size() == 12);
  const MeshAttributes& a = mesh->attributes;
  CHECK(a.layout == AttributeLayout{true, 1, false});
  for (std::size_t f = 0; f < 12; ++f)
    for (int k = 0; k < 3; ++k) {
      const double* c = a.corner(f, k);
      CHECK(Vec3(c[0], c[1], c[2]).norm() == Approx(1.0).epsilon(1e-6));
      // The file's TEXCOORD_0 accessor declares min [0, 0] and max [6, 1] (u wraps around the cube).
      CHECK((c[3] >= 0.0 && c[3] <= 6.0 && c[4] >= 0.0 && c[4] <= 1.0));
    }
  // One material is used (assimp adds an unused default): one slot, its texture embedded.
  REQUIRE(a.slots.size() == 1);
  CHECK(a.materials == std::vector<std::int32_t>(12, 0));
  CHECK(a.slots[0].name == "Texture");
  REQUIRE(a.slots[0].base_color_image);
  CHECK(a.slots[0].base_color_image->mime_type == "image/png");
  const std::vector<std::uint8_t>& png = a.slots[0].base_color_image->bytes;
  REQUIRE(png.size() > 8);
  CHECK(std::vector<std::uint8_t>(png.begin(), png.begin() + 8) ==
        std::vector<std::uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
  // Seams never open the solid: welding positions leaves the cube's 8 corners, closed.
  const Result<ValidationReport> report = validate_solid(*mesh, box.string());
  REQUIRE(report.ok());
  CHECK(mesh->vertices.size() == 8);
  CHECK(is_closed_and_oriented(*mesh));
}

TEST_CASE("read_asset: hostile glTF files give one-line errors", "[assets][hostile]") {
  const fs::path dir = scratch("hostile");
  const std::string box = bytes_of(kGltf / "BoxTextured-glTF-Binary" / "BoxTextured.glb");
  REQUIRE(box.size() > 1000);
  const fs::path truncated = dir / "truncated.glb";
  std::ofstream(truncated, std::ios::binary) << box.substr(0, box.size() / 2);
  one_line_error(truncated);
  const fs::path empty = dir / "empty.glb";
  std::ofstream(empty, std::ios::binary) << "";
  one_line_error(empty);
  for (const fs::path input : {kGltf / "IndexOutOfRange" / "IndexOutOfRange.gltf", kGltf / "MissingBin" / "BoxTextured.gltf",
                               kGltf / "BoxWithInfinites-glTF-Binary" / "BoxWithInfinites.glb"})
    REQUIRE(fs::exists(input));  // the hostile inputs are data: missing, the test fails
  // assimp drops the faces whose indices are out of range and warns: refused here.
  CHECK_THAT(one_line_error(kGltf / "IndexOutOfRange" / "IndexOutOfRange.gltf"), Contains("out-of-range"));
  one_line_error(kGltf / "IndexOutOfRange" / "AllIndicesOutOfRange.gltf");
  CHECK_THAT(one_line_error(kGltf / "MissingBin" / "BoxTextured.gltf"), Contains("BoxTextured0.bin"));
  CHECK_THAT(one_line_error(kGltf / "BoxWithInfinites-glTF-Binary" / "BoxWithInfinites.glb"),
             Contains("mesh 0") && Contains("non-finite"));
  CHECK_THAT(one_line_error(dir / "absent.glb"), Contains("cannot open"));
  CHECK_THAT(one_line_error(dir / "mesh.nosuchformat"), Contains("unknown mesh format"));
}

TEST_CASE("read_asset: glTF that assimp would crash on or read past is refused before import", "[assets][hostile]") {
  // Each case edits the textured box's JSON in place (same length, so the container stays valid)
  // the way the fuzzer found assimp 5.2 crashing or reading out of bounds.
  const fs::path dir = scratch("guards");
  const std::string box = bytes_of(kGltf / "BoxTextured-glTF-Binary" / "BoxTextured.glb");
  REQUIRE(box.size() > 1000);
  const auto edited = [&](const std::string& name, const std::string& from, const std::string& to) {
    REQUIRE(from.size() == to.size());
    std::string bytes = box;
    const std::size_t at = bytes.find(from);
    REQUIRE(at != std::string::npos);
    bytes.replace(at, from.size(), to);
    const fs::path path = dir / (name + ".glb");
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  };
  CHECK_THAT(one_line_error(edited("line_loop", "\"mode\":4", "\"mode\":2")), Contains("line loop"));
  CHECK_THAT(one_line_error(edited("mime", "\"image/png\"", "\"image*png\"")), Contains("MIME type"));
  CHECK_THAT(one_line_error(edited("utf8", "\"image/png\"", "\"\x9f\x98\x9a\xc8" "a/png\"")), Contains("does not parse"));
  CHECK_THAT(one_line_error(edited("bounds", "\"byteOffset\":288", "\"byteOffset\":289")),
             Contains("accessor 2 ends past its buffer view"));
  // Too few entries for one primitive of the mode: assimp 5.2 computes count - 2 (strip, fan) or
  // count - 1 (line strip) faces in unsigned arithmetic and writes the first of them.
  const auto mode_count = [&](const std::string& name, char mode, const std::string& count) {
    const fs::path mode_edited = edited(name, "\"mode\":4", std::string("\"mode\":") + mode);
    std::string bytes = bytes_of(mode_edited);
    const std::string from = "\"count\":36,", to = "\"count\":" + count + std::string(2 - count.size(), ' ') + ",";
    bytes.replace(bytes.find(from), from.size(), to);
    std::ofstream(mode_edited, std::ios::binary | std::ios::trunc) << bytes;
    return one_line_error(mode_edited);
  };
  CHECK_THAT(mode_count("strip", '5', "1"), Contains("mesh 0 primitive 0 is triangle strip (mode 5) with 1 index entries") &&
                                                 Contains("at least 3"));
  CHECK_THAT(mode_count("fan", '6', "2"), Contains("triangle fan") && Contains("at least 3"));
  CHECK_THAT(mode_count("line_strip", '3', "0"), Contains("line strip") && Contains("at least 2"));
  CHECK_THAT(mode_count("lines", '1', "1"), Contains("lines (mode 1) with 1 index") && Contains("multiple of 2"));
  CHECK_THAT(mode_count("triangles", '4', "35"), Contains("multiple of 3"));
  CHECK_THAT(one_line_error(edited("mode", "\"mode\":4", "\"mode\":9")), Contains("no valid mode"));
  CHECK_THAT(one_line_error(edited("indices", "\"indices\":0", "\"indices\":7")), Contains("no valid index accessor"));
  // A key twice in one object: the checks would read the second "meshes" (no primitives) and assimp
  // the first (here a triangle strip of one index entry).
  {
    const fs::path strip = edited("twice", "\"mode\":4", "\"mode\":5");
    std::string bytes = bytes_of(strip);
    bytes.replace(bytes.find("\"count\":36,"), 11, "\"count\":1 ,");
    bytes.replace(bytes.find("\"images\":"), 9, "\"meshes\":");
    std::ofstream(strip, std::ios::binary | std::ios::trunc) << bytes;
    CHECK_THAT(one_line_error(strip), Contains("the key \"meshes\" twice in one object"));
  }
  std::string chunk = box;
  chunk[15] = '\x0d';  // the JSON chunk claims 200 MB
  std::ofstream(dir / "chunk.glb", std::ios::binary) << chunk;
  CHECK_THAT(one_line_error(dir / "chunk.glb"), Contains("chunk 0's length"));
  std::ofstream(dir / "text.glb", std::ios::binary) << "solid not a binary glTF, only text\n";
  CHECK_THAT(one_line_error(dir / "text.glb"), Contains("no binary glTF magic"));
}

TEST_CASE("read_asset: the size limit holds before import, the counts after it", "[assets][hostile]") {
  const fs::path box = kGltf / "BoxTextured-glTF-Binary" / "BoxTextured.glb";
  MeshReadLimits small;
  small.max_file_bytes = 1000;
  CHECK_THAT(one_line_error(box, small), Contains("larger than the limit of 1000 bytes"));
  MeshReadLimits triangles;
  triangles.max_triangles = 11;
  CHECK_THAT(one_line_error(box, triangles), Contains("triangle count 12 exceeds the limit of 11"));
  MeshReadLimits vertices;
  vertices.max_vertices = 23;
  CHECK_THAT(one_line_error(box, vertices), Contains("vertex count 24 exceeds the limit of 23"));
}

TEST_CASE("read_asset: .off and .obj go to the project's readers, assimp's formats are recognised", "[assets]") {
  const fs::path dir = scratch("dispatch");
  std::ofstream(dir / "t.obj", std::ios::binary) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const Result<Mesh> obj = read_asset(dir / "t.obj");
  REQUIRE(obj.ok());
  CHECK(obj->triangles.size() == 4);
  CHECK(obj->attributes.empty());
  for (const char* ext : {".glb", ".GLTF", ".fbx", ".ply", ".stl", ".dae", ".3ds", "obj", ".off"}) CHECK(is_asset_extension(ext));
  CHECK_FALSE(is_asset_extension(".nosuchformat"));
  CHECK_FALSE(is_asset_extension(""));
  // An ASCII STL through assimp: a tetrahedron (three vertices per facet, welded by validation).
  const std::string stl = "solid t\n"
                          "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
                          "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
                          "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
                          "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\n"
                          "endsolid t\n";
  std::ofstream(dir / "t.stl", std::ios::binary) << stl;
  Result<Mesh> tetra = read_asset(dir / "t.stl");
  REQUIRE(tetra.ok());
  CHECK(tetra->triangles.size() == 4);
  REQUIRE(validate_solid(*tetra, "t.stl").ok());
  CHECK(tetra->vertices.size() == 4);
}
