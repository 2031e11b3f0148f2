// Hostile assets, their references (algorithms/core/asset_reference.h): an OBJ's material libraries,
// an MTL's textures and a glTF's buffers and images are read, or carried into the fragments' files,
// only as regular files inside the asset's own folder; a reference that leaves it, names a device or
// a FIFO, or passes the size limit is refused with a message naming it, and nothing waits on it.
// The OBJ and MTL readers stay linear in repeated libraries, many materials and large polygons.

#include "algorithms/assets/read_asset.h"
#include "algorithms/core/asset_reference.h"
#include "algorithms/core/mesh_io.h"
#include "tests/hostile/hostile_support.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

std::string error_of(const Result<Mesh>& mesh) { return mesh.ok() ? std::string("(no error)") : mesh.error().message; }

/// A closed tetrahedron as an OBJ that names `library` and uses material "m".
std::string tetra_obj(const std::string& library) {
  return "mtllib " + library + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl m\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
}

/// The tetrahedron's buffer for a glTF: 4 float positions, then 12 uint16 indices (72 bytes).
std::string tetra_buffer() {
  const float p[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint16_t t[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
  std::string bytes(72, '\0');
  std::memcpy(bytes.data(), p, 48);
  std::memcpy(bytes.data() + 48, t, 24);
  return bytes;
}

/// A glTF naming its buffer `buffer_uri` and, when not empty, a base colour texture `image_uri`.
std::string tetra_gltf(const std::string& buffer_uri, const std::string& image_uri = {}) {
  std::string material, images;
  if (!image_uri.empty()) {
    material = R"(,"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],"textures":[{"source":0}])";
    images = R"(,"images":[{"uri":")" + image_uri + R"("}])";
  }
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1)" +
         std::string(image_uri.empty() ? "" : R"(,"material":0)") + R"(}]}],)"
         R"("buffers":[{"uri":")" + buffer_uri + R"(","byteLength":72}],)"
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},)"
         R"({"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}])" + material + images + "}";
}

}  // namespace

TEST_CASE("asset references: the text of a reference is a relative path of plain names", "[hostile][assets]") {
  CHECK(check_reference_text("m.mtl", "x").ok());
  CHECK(check_reference_text("textures/brick.png", "x").ok());
  CHECK(check_reference_text("my texture.png", "x").ok());
  for (const char* bad : {"", "/etc/passwd", "../m.mtl", "a/../../b", "textures/..", "c:\\x.png", "file:///etc/passwd",
                          "http://host/x.bin", "a\\b.png", "a\nb"}) {
    INFO(bad);
    CHECK_FALSE(check_reference_text(bad, "x").ok());
  }
}

TEST_CASE("asset references: an OBJ's material libraries and textures stay in its folder", "[hostile][assets][obj]") {
  const fs::path dir = hostile_scratch("obj_references");
  const fs::path inner = dir / "asset";
  fs::create_directories(inner);
  put_file(dir / "outside.mtl", "newmtl m\nKd 1 0 0\n");
  put_file(inner / "m.mtl", "newmtl m\nKd 0 1 0\nmap_Kd textures/brick.png\n");
  const Result<Mesh> ok = read_mesh(put_file(inner / "ok.obj", tetra_obj("m.mtl")));
  REQUIRE(ok.ok());
  CHECK(ok->attributes.slots.at(0).base_color_texture == "textures/brick.png");

  CHECK_THAT(error_of(read_mesh(put_file(inner / "up.obj", tetra_obj("../outside.mtl")))),
             Catch::Contains("'../outside.mtl' refused: it leaves the asset's folder"));
  CHECK_THAT(error_of(read_mesh(put_file(inner / "abs.obj", tetra_obj((dir / "outside.mtl").string())))),
             Catch::Contains("an absolute path"));
  fs::create_symlink(dir / "outside.mtl", inner / "link.mtl");
  CHECK_THAT(error_of(read_mesh(put_file(inner / "link.obj", tetra_obj("link.mtl")))),
             Catch::Contains("outside the asset's folder"));
  REQUIRE(::mkfifo((inner / "fifo.mtl").c_str(), 0600) == 0);
  CHECK_THAT(error_of(read_mesh(put_file(inner / "fifo.obj", tetra_obj("fifo.mtl")))),
             Catch::Contains("not a regular file"));
  put_file(inner / "shadow.mtl", "newmtl m\nmap_Kd /etc/shadow\n");
  CHECK_THAT(error_of(read_mesh(put_file(inner / "shadow.obj", tetra_obj("shadow.mtl")))),
             Catch::Contains("texture '/etc/shadow' refused: an absolute path"));
  put_file(inner / "escape.mtl", "newmtl m\nmap_Kd -s 1 1 1 ../../secret.png\n");
  CHECK_THAT(error_of(read_mesh(put_file(inner / "escape.obj", tetra_obj("escape.mtl")))),
             Catch::Contains("texture '../../secret.png' refused"));
}

TEST_CASE("asset references: repeated libraries, many materials and a large polygon read in one pass",
          "[hostile][assets][obj]") {
  const fs::path dir = hostile_scratch("obj_linear");
  // One library named 4,000 times is read once.
  put_file(dir / "m.mtl", "newmtl m\nKd 0 1 0\n");
  std::string repeated;
  for (int i = 0; i < 4000; ++i) repeated += "mtllib m.mtl\n";
  const Result<Mesh> once = read_mesh(put_file(dir / "repeated.obj", repeated + tetra_obj("m.mtl")));
  REQUIRE(once.ok());
  CHECK(once->attributes.slots.size() == 1);
  // 60,000 materials defined, redefined and used: the last definition wins for each.
  std::string library, uses = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  for (int i = 0; i < 60000; ++i) library += "newmtl m" + std::to_string(i) + "\nKd 1 0 0\n";
  for (int i = 0; i < 60000; ++i) library += "newmtl m" + std::to_string(i) + "\nKd 0 0 1\n";
  for (int i = 0; i < 60000; ++i) uses += "usemtl m" + std::to_string(i) + "\n";
  uses += "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  put_file(dir / "many.mtl", library);
  const Result<Mesh> many = read_mesh(put_file(dir / "many.obj", "mtllib many.mtl\n" + uses));
  REQUIRE(many.ok());
  REQUIRE(many->attributes.slots.size() == 60000);
  CHECK(many->attributes.slots.back().base_color[2] == 1.0);
  CHECK(many->attributes.slots.back().base_color[0] == 0.0);
  // A convex polygon of 200,000 corners, each with its normal: n - 2 triangles, each corner's normal
  // the one its vertex was given.
  const int n = 200000;
  std::string polygon;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / n;
    polygon += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  for (int i = 0; i < n; ++i) polygon += "vn 0 0 " + std::to_string(1 + i % 7) + "\n";
  polygon += "f";
  for (int i = 1; i <= n; ++i) polygon += " " + std::to_string(i) + "//" + std::to_string(i);
  polygon += "\n";
  MeshReadLimits limits;
  const Result<Mesh> big = read_obj(put_file(dir / "polygon.obj", polygon), limits);
  REQUIRE(big.ok());
  CHECK(big->triangles.size() == static_cast<std::size_t>(n - 2));
  for (std::size_t f = 0; f < big->triangles.size(); f += 997)
    for (int k = 0; k < 3; ++k)
      CHECK(big->attributes.corner(f, k)[2] == 1 + big->triangles[f][k] % 7);
}

TEST_CASE("asset references: a glTF's buffers and images stay in its folder", "[hostile][assets][gltf]") {
  const fs::path dir = hostile_scratch("gltf_references");
  const fs::path inner = dir / "asset";
  fs::create_directories(inner);
  put_file(inner / "tet.bin", tetra_buffer());
  put_file(dir / "outside.bin", tetra_buffer());
  const Result<Mesh> ok = read_asset(put_file(inner / "ok.gltf", tetra_gltf("tet.bin")));
  INFO(error_of(ok));
  REQUIRE(ok.ok());
  CHECK(ok->triangles.size() == 4);

  CHECK_THAT(error_of(read_asset(put_file(inner / "up.gltf", tetra_gltf("../outside.bin")))),
             Catch::Contains("refused"));
  CHECK_THAT(error_of(read_asset(put_file(inner / "abs.gltf", tetra_gltf((dir / "outside.bin").string())))),
             Catch::Contains("refused"));
  for (const char* system_file : {"/etc/passwd", "/proc/self/mem", "/dev/zero"}) {
    INFO(system_file);
    CHECK_THAT(error_of(read_asset(put_file(inner / "sys.gltf", tetra_gltf(std::string("../../../../..") + system_file)))),
               Catch::Contains("refused"));
  }
  fs::create_symlink(dir / "outside.bin", inner / "link.bin");
  CHECK_THAT(error_of(read_asset(put_file(inner / "link.gltf", tetra_gltf("link.bin")))),
             Catch::Contains("outside the asset's folder"));
  REQUIRE(::mkfifo((inner / "fifo.bin").c_str(), 0600) == 0);
  CHECK_THAT(error_of(read_asset(put_file(inner / "fifo.gltf", tetra_gltf("fifo.bin")))),
             Catch::Contains("not a regular file"));
  // A buffer past the size limit is refused on its size, before it is read.
  put_file(inner / "padded.bin", tetra_buffer() + std::string(4000, '\0'));
  const fs::path padded = put_file(inner / "big.gltf", tetra_gltf("padded.bin"));
  MeshReadLimits small;
  small.max_file_bytes = 2000;
  REQUIRE(fs::file_size(padded) < small.max_file_bytes);
  CHECK_THAT(error_of(read_asset(padded, small)), Catch::Contains("past the limit"));
  // A texture named outside the folder would be written into the fragments' files: refused.
  CHECK_THAT(error_of(read_asset(put_file(inner / "image.gltf", tetra_gltf("tet.bin", "../../etc/shadow")))),
             Catch::Contains("texture '../../etc/shadow' refused"));
  const Result<Mesh> textured = read_asset(put_file(inner / "textured.gltf", tetra_gltf("tet.bin", "brick.png")));
  INFO(error_of(textured));
  REQUIRE(textured.ok());
  CHECK(textured->attributes.slots.at(0).base_color_texture == "brick.png");
}
