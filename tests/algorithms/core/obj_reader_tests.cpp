#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/material_library.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::Equals;
namespace fs = std::filesystem;

namespace {

/// A fresh folder for one test, named after it.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shatter_obj_reader_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path put(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string error_of(const Result<Mesh>& mesh) { return mesh.ok() ? "(no error)" : mesh.error().message; }

/// The UV the test cube's vertices carry: an affine function of the position.
Vec2 uv_at(const Vec3& p) { return Vec2(0.25 + 0.5 * p.x() - 0.125 * p.z(), 0.75 * p.y() + 0.125 * p.z()); }

/// A unit cube as an exporter writes it (Blender's order of statements): 8 vertices, one `vt` per
/// vertex (uv_at), one `vn` per face, 6 quads `v/vt/vn`; two faces before any usemtl, two in "stone",
/// two in "brick"; the library in a subfolder.
std::string exported_cube() {
  std::string obj = "# Blender 3.6 OBJ File: ''\n# www.blender.org\nmtllib mats/cube.mtl\no Cube\n";
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  char line[128];
  for (const Vec3& p : corners) {
    std::snprintf(line, sizeof line, "v %g %g %g\n", p.x(), p.y(), p.z());
    obj += line;
  }
  for (const Vec3& p : corners) {
    const Vec2 uv = uv_at(p);
    std::snprintf(line, sizeof line, "vt %.17g %.17g\n", uv.x(), uv.y());
    obj += line;
  }
  obj += "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\ns 0\n";
  // Outward, counter-clockwise: bottom, top, front (y = 0), back, left (x = 0), right.
  const int quads[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5}, {4, 8, 7, 3}, {1, 5, 8, 4}, {2, 3, 7, 6}};
  for (int q = 0; q < 6; ++q) {
    if (q == 2) obj += "usemtl stone\n";
    if (q == 4) obj += "usemtl brick\n";
    obj += "f";
    for (const int v : quads[q]) obj += " " + std::to_string(v) + "/" + std::to_string(v) + "/" + std::to_string(q + 1);
    obj += "\n";
  }
  return obj;
}

const char* kCubeMtl =
    "# Blender 3.6 MTL File: 'None'\n# Material Count: 2\n\nnewmtl brick\nNs 250.000000\nKa 1.000000 1.000000 1.000000\n"
    "Kd 0.8 0.25 0.125\nKs 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 0.5\nillum 2\n"
    "map_Kd brick.png\n\nnewmtl stone\nNs 250\nKd 0.5 0.5 0.5\nTr 0.25\nillum 2\nmap_Bump -bm 1 stone_n.png\n";

}  // namespace

TEST_CASE("obj reader: an exported OBJ gives per-corner normals, UVs and materials from its library", "[mesh_io][obj]") {
  const fs::path dir = scratch("exported");
  put(dir / "mats" / "cube.mtl", kCubeMtl);
  const Result<Mesh> mesh = read_obj(put(dir / "cube.obj", exported_cube()));
  REQUIRE(mesh.ok());
  REQUIRE(mesh->triangles.size() == 12);
  const MeshAttributes& a = mesh->attributes;
  CHECK(a.layout == AttributeLayout{true, 1, false});
  REQUIRE(a.corners.size() == 12 * 3 * 5);
  for (std::size_t f = 0; f < 12; ++f) {
    const Triangle& t = mesh->triangles[f];
    const Vec3 geometric = (mesh->vertices[t[1]] - mesh->vertices[t[0]]).cross(mesh->vertices[t[2]] - mesh->vertices[t[0]]).normalized();
    for (int k = 0; k < 3; ++k) {
      const double* c = a.corner(f, k);
      // The face's vn is its outward axis; the vt the vertex's affine UV.
      CHECK(Vec3(c[0], c[1], c[2]) == geometric);
      const Vec2 uv = uv_at(mesh->vertices[t[static_cast<std::size_t>(k)]]);
      CHECK(c[3] == uv.x());
      CHECK(c[4] == uv.y());
    }
  }
  // Slots in order of first use, then "default" for the faces before the first usemtl.
  REQUIRE(a.slots.size() == 3);
  CHECK(a.slots[0].name == "stone");
  CHECK(a.slots[1].name == "brick");
  CHECK(a.slots[2].name == "default");
  CHECK(a.materials == std::vector<std::int32_t>{2, 2, 2, 2, 0, 0, 0, 0, 1, 1, 1, 1});
  CHECK(a.slots[1].base_color == std::array<double, 4>{0.8, 0.25, 0.125, 0.5});
  CHECK(a.slots[0].base_color == std::array<double, 4>{0.5, 0.5, 0.5, 0.75});  // Tr 0.25
  CHECK(a.slots[1].base_color_texture == "mats/brick.png");  // relative to the OBJ's folder
  CHECK(a.slots[0].base_color_texture.empty());             // a bump map is not a base colour
  CHECK(a.slots[2].base_color == std::array<double, 4>{1, 1, 1, 1});
}

TEST_CASE("obj reader: a channel only some corners have is dropped, the others kept", "[mesh_io][obj]") {
  const fs::path dir = scratch("partial");
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0 0\nvn 0 0 -1\nvn 1 1 1\n"
                          "f 1/1/1 3/2/1 2/1/1\nf 1//2 2//2 4//2\n";
  const Result<Mesh> mesh = read_obj(put(dir / "partial.obj", obj));
  REQUIRE(mesh.ok());
  CHECK(mesh->attributes.layout == AttributeLayout{true, 0, false});
  CHECK(mesh->attributes.slots.empty());
  REQUIRE(mesh->attributes.corners.size() == 2 * 3 * 3);
  CHECK(Vec3(mesh->attributes.corner(1, 2)[0], mesh->attributes.corner(1, 2)[1], mesh->attributes.corner(1, 2)[2]) ==
        Vec3(1, 1, 1));  // kept as written
  // Corners without vt and vn, no usemtl: no attributes at all, whatever vt and vn lines the file has.
  const Result<Mesh> plain = read_obj(put(dir / "plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nvt 0 0\nvn 0 0 1\n"));
  REQUIRE(plain.ok());
  CHECK(plain->attributes.empty());
}

TEST_CASE("obj reader: usemtl without mtllib gives white slots by name", "[mesh_io][obj]") {
  const fs::path dir = scratch("no_library");
  const Result<Mesh> mesh =
      read_obj(put(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl glass\nf 1 3 2\nusemtl (null)\nf 1 2 4\n"));
  REQUIRE(mesh.ok());
  REQUIRE(mesh->attributes.slots.size() == 2);
  CHECK(mesh->attributes.slots[0].name == "glass");
  CHECK(mesh->attributes.slots[1].name == "(null)");
  CHECK(mesh->attributes.materials == std::vector<std::int32_t>{0, 1});
  CHECK(mesh->attributes.layout.empty());
}

TEST_CASE("obj reader: a missing library or a material it lacks is a one-line error naming both", "[mesh_io][obj]") {
  const fs::path dir = scratch("bad_library");
  put(dir / "cube.mtl", kCubeMtl);
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const fs::path missing = put(dir / "missing.obj", "mtllib nope.mtl\n" + tri + "f 1 2 3\n");
  CHECK_THAT(error_of(read_obj(missing)),
             Equals(missing.string() + ":1: material library 'nope.mtl' not found (looked for " + (dir / "nope.mtl").string() + ")"));
  const fs::path unknown = put(dir / "unknown.obj", "mtllib cube.mtl\n" + tri + "usemtl marble\nf 1 2 3\n");
  CHECK_THAT(error_of(read_obj(unknown)), Equals(unknown.string() + ":5: material 'marble' not in 'cube.mtl'"));
  const fs::path bad_mtl = put(dir / "bad.mtl", "Kd 1 1 1\n");
  const fs::path uses_bad = put(dir / "uses_bad.obj", "mtllib bad.mtl\n" + tri + "f 1 2 3\n");
  const std::string message = error_of(read_obj(uses_bad));
  CHECK_THAT(message, Contains(uses_bad.string() + ":1: material library: " + bad_mtl.string() + ":1: 'Kd' before the first 'newmtl'"));
  CHECK(message.find('\n') == std::string::npos);
  const fs::path vt_range = put(dir / "vt_range.obj", tri + "vt 0 0\nf 1/1 2/2 3/1\n");
  CHECK_THAT(error_of(read_obj(vt_range)), Contains(vt_range.string() + ":5: face references texture coordinate 2 out of range"));
  const fs::path vn_bad = put(dir / "vn_bad.obj", tri + "vn 0 0 nan\nf 1//1 2//1 3//1\n");
  CHECK_THAT(error_of(read_obj(vn_bad)), Contains(vn_bad.string() + ":4: vn: "));
}

TEST_CASE("obj writer: an attributed mesh round-trips its normals, UVs, materials and groups", "[mesh_io][obj]") {
  const fs::path dir = scratch("round_trip");
  Mesh mesh = make_box(Vec3(1.0 / 3.0, 0.7, 2.0), Vec3(0.1, -0.2, 0.3));
  const std::size_t faces = mesh.triangles.size();
  MeshAttributes& a = mesh.attributes;
  a.layout = AttributeLayout{true, 1, false};
  MaterialSlot paint;
  paint.name = "paint";
  paint.base_color = {0.1, 0.2, 1.0 / 3.0, 0.9};
  paint.base_color_texture = "paint.png";
  a.slots = {paint};
  a.materials.assign(faces, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).normalized();
    for (int k = 0; k < 3; ++k) {
      const Vec2 uv = uv_at(mesh.vertices[t[static_cast<std::size_t>(k)]]);
      a.corners.insert(a.corners.end(), {n.x(), n.y(), n.z(), uv.x(), uv.y()});
    }
  }
  prepare_cut_faces(mesh, 0.5);  // adds the interior slot
  for (std::size_t f = 0; f < faces; f += 4) {
    mesh.tags[f] = FaceTag::cut;
    a.materials[f] = a.cut.material;
  }
  REQUIRE(write_obj(mesh, dir / "piece.obj").ok());
  REQUIRE(fs::exists(dir / "piece.mtl"));
  const Result<Mesh> back = read_obj(dir / "piece.obj");
  REQUIRE(back.ok());
  CHECK(back->vertices == mesh.vertices);
  CHECK(back->attributes.layout == a.layout);
  CHECK(back->attributes.slots == a.slots);
  // Faces come back grouped (surface, then cut): match each by its vertex triple.
  REQUIRE(back->triangles.size() == faces);
  for (std::size_t g = 0; g < faces; ++g) {
    const auto f = static_cast<std::size_t>(std::find(mesh.triangles.begin(), mesh.triangles.end(), back->triangles[g]) -
                                            mesh.triangles.begin());
    REQUIRE(f < faces);
    CHECK(back->tags[g] == mesh.tags[f]);
    CHECK(back->attributes.materials[g] == a.materials[f]);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 5; ++i)
        CHECK(std::abs(back->attributes.corner(g, k)[i] - a.corner(f, k)[i]) <= 1e-15 * std::max(1.0, std::abs(a.corner(f, k)[i])));
  }
}

TEST_CASE("obj writer: a mesh without attributes is written as before, byte for byte", "[mesh_io][obj]") {
  const fs::path dir = scratch("plain_bytes");
  Mesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 1.0 / 3.0, 0), Vec3(0, 0, -2)};
  mesh.add_triangle(0, 2, 1, FaceTag::surface);
  mesh.add_triangle(0, 1, 3, FaceTag::cut);
  mesh.add_triangle(1, 2, 3, FaceTag::surface);
  REQUIRE(write_obj(mesh, dir / "plain.obj").ok());
  std::ifstream in(dir / "plain.obj", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text ==
        "# shatterbench mesh\nv 0 0 0\nv 0.10000000000000001 0 0\nv 0 0.33333333333333331 0\nv 0 0 -2\n"
        "g surface\nf 1 3 2\nf 2 3 4\ng cut\nf 1 2 4\n");
  CHECK_FALSE(fs::exists(dir / "plain.mtl"));
}

TEST_CASE("material library: read_mtl reads what write_mtl writes", "[mesh_io][obj]") {
  const fs::path dir = scratch("mtl");
  MaterialSlot a, b;
  a.name = "a b";  // a name with a space
  a.base_color = {0.1, 0.2, 0.3, 1.0};
  b.name = "b";
  b.base_color = {1.0 / 3.0, 0.0, 1.0, 0.25};
  b.base_color_texture = "tex/b.png";
  const std::vector<MaterialSlot> slots = {a, b};
  REQUIRE(write_mtl(slots, dir / "m.mtl").ok());
  const Result<std::vector<MaterialSlot>> back = read_mtl(dir / "m.mtl");
  REQUIRE(back.ok());
  CHECK(*back == slots);
  // Colours past [0, 1] are clamped; a grey Kd has one number; options before map_Kd's file.
  put(dir / "n.mtl", "newmtl x\nKd 1.5\nd -0.5\nmap_Kd -s 2 2 1 -o 0.5 0 0 wood.jpg\n");
  const Result<std::vector<MaterialSlot>> n = read_mtl(dir / "n.mtl");
  REQUIRE(n.ok());
  CHECK((*n)[0].base_color == std::array<double, 4>{1, 1, 1, 0});
  CHECK((*n)[0].base_color_texture == "wood.jpg");
}
