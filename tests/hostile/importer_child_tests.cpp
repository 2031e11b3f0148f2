// Third-party importers in a child (harness/cases/isolated_import.h): a file on which assimp crashes,
// allocates without bound or runs without end costs the child, never the process, and is one line
// naming the file; a good file comes back from the child exactly as assimp read it.

#include "algorithms/assets/mesh_codec.h"
#include "algorithms/assets/read_asset.h"
#include "harness/cases/isolated_import.h"
#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <string>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

std::string error_of(const Result<Mesh>& mesh) { return mesh.ok() ? std::string("(no error)") : mesh.error().message; }

/// A COLLADA scene whose one triangle sits `depth` nodes deep (assimp recurses once per node).
std::string nested_collada(int depth) {
  std::string nodes, ends;
  for (int i = 0; i < depth; ++i) {
    nodes += "<node>";
    ends += "</node>";
  }
  return R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">)"
         R"(<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0)"
         R"(</float_array><technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>)"
         R"(<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>)"
         R"(<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1">)"
         R"(<input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries>)"
         R"(<library_visual_scenes><visual_scene id="s">)" +
         nodes + R"(<instance_geometry url="#g"/>)" + ends +
         R"(</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>)";
}

}  // namespace

TEST_CASE("importer child: a good asset comes back exactly as assimp reads it", "[hostile][assets][import]") {
  const fs::path asset = fs::path(SHATTER_SOURCE_DIR) / "data" / "assets" / "BoxTextured.glb";
  REQUIRE(fs::exists(asset));  // scripts/fetch-meshes extracts it
  const Result<Mesh> here = read_asset(asset);
  const Result<Mesh> child = read_asset_isolated(asset);
  REQUIRE(here.ok());
  INFO(error_of(child));
  REQUIRE(child.ok());
  CHECK(child->vertices == here->vertices);
  CHECK(child->triangles == here->triangles);
  CHECK(child->tags == here->tags);
  CHECK(child->attributes.layout == here->attributes.layout);
  CHECK(std::equal(child->attributes.corners.begin(), child->attributes.corners.end(), here->attributes.corners.begin(),
                   here->attributes.corners.end()));
  CHECK(child->attributes.materials == here->attributes.materials);
  REQUIRE(child->attributes.slots.size() == here->attributes.slots.size());
  for (std::size_t i = 0; i < here->attributes.slots.size(); ++i) {
    const MaterialSlot& a = child->attributes.slots[i];
    const MaterialSlot& b = here->attributes.slots[i];
    CHECK(a.name == b.name);
    CHECK(a.base_color == b.base_color);
    CHECK(a.base_color_texture == b.base_color_texture);
    REQUIRE((a.base_color_image == nullptr) == (b.base_color_image == nullptr));
    if (a.base_color_image) CHECK(a.base_color_image->bytes == b.base_color_image->bytes);
  }
}

TEST_CASE("importer child: a damaged answer is refused, never used", "[hostile][assets][import]") {
  Mesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  mesh.tags.assign(4, FaceTag::surface);
  const std::string bytes = encode_mesh(mesh);
  REQUIRE(decode_mesh(bytes, "x").ok());
  // Every prefix is incomplete; every single-byte change of a count or an index is caught or harmless.
  for (std::size_t n = 0; n < bytes.size(); ++n) CHECK_FALSE(decode_mesh(bytes.substr(0, n), "x").ok());
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x5a);
    const Result<Mesh> back = decode_mesh(damaged, "x");
    if (!back) continue;
    for (const Triangle& t : back->triangles)
      for (const std::int32_t i : t) CHECK((i >= 0 && static_cast<std::size_t>(i) < back->vertices.size()));
    for (const Vec3& v : back->vertices) CHECK(v.allFinite());
  }
}

TEST_CASE("importer child: assimp's crash, runaway allocation or time is one line naming the file",
          "[hostile][assets][import]") {
  const fs::path dir = hostile_scratch("importer_child");
  // 200,000 nested nodes: assimp's recursion overflows its stack.
  const fs::path deep = put_file(dir / "deep.dae", nested_collada(200000));
  const Result<Mesh> crashed = read_asset_isolated(deep);
  REQUIRE_FALSE(crashed.ok());
  CHECK_THAT(crashed.error().message, Catch::Contains(deep.string()));
  const CliRun cli = run_cli_argv({"fracture", "--mesh", deep.string(), "--algo", "plane-slice", "--fragments", "5"});
  CHECK(cli.exit_code == 2);
  CHECK(line_count(cli.err) == 1);
  CHECK_THAT(cli.err, Catch::Contains("deep.dae"));
  // A 200-byte PLY that declares 150 million vertices.
  const fs::path ply = put_file(dir / "huge.ply",
                                "ply\nformat binary_little_endian 1.0\nelement vertex 150000000\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                "end_header\n");
  ImportLimits tight;
  tight.memory_bytes = 1ULL << 30;
  tight.time_s = 20.0;
  const Result<Mesh> huge = read_asset_isolated(ply, {}, tight);
  REQUIRE_FALSE(huge.ok());
  CHECK_THAT(huge.error().message, Catch::Contains(ply.string()));
}
