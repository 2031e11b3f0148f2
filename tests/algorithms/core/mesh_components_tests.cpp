#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/mesh_components.h"
#include "algorithms/core/primitives.h"

#include <catch2/catch.hpp>

#include <array>
#include <utility>
#include <vector>

using namespace shatter;

// Parts are counted against meshes built from known pieces: n boxes placed apart make n parts, each
// the box it came from (its triangles in order, each with the same corner positions; a part's
// vertices are numbered by first use).

namespace {

std::vector<std::array<Vec3, 3>> corner_positions(const Mesh& mesh) {
  std::vector<std::array<Vec3, 3>> out;
  for (const Triangle& t : mesh.triangles)
    out.push_back({mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
                   mesh.vertices[static_cast<std::size_t>(t[2])]});
  return out;
}

}  // namespace

TEST_CASE("components: one box is one part, moved out whole, and without a vertex no triangle uses", "[components]") {
  const Mesh box = make_box(Vec3(1, 2, 3));
  Mesh moved = box;
  const std::vector<Mesh> one = connected_components(std::move(moved));
  REQUIRE(one.size() == 1);
  CHECK(one[0].vertices == box.vertices);
  CHECK(one[0].triangles == box.triangles);

  Mesh with_spare = box;
  with_spare.add_vertex(Vec3(9, 9, 9));  // used by no triangle
  for (const bool consume : {false, true}) {
    Mesh input = with_spare;
    const std::vector<Mesh> parts = consume ? connected_components(std::move(input)) : connected_components(input);
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].vertices.size() == box.vertices.size());
    CHECK(corner_positions(parts[0]) == corner_positions(box));
  }
}

TEST_CASE("components: boxes apart are parts of their own, in order of their first triangle", "[components]") {
  Mesh three;
  for (int k = 0; k < 3; ++k) append_mesh(three, make_box(Vec3(1, 1, 1), Vec3(3.0 * k, 0, 0)));
  for (const bool consume : {false, true}) {
    Mesh input = three;
    const std::vector<Mesh> parts = consume ? connected_components(std::move(input)) : connected_components(input);
    REQUIRE(parts.size() == 3);
    for (int k = 0; k < 3; ++k) {
      const Mesh expected = make_box(Vec3(1, 1, 1), Vec3(3.0 * k, 0, 0));
      CHECK(parts[static_cast<std::size_t>(k)].vertices.size() == expected.vertices.size());
      CHECK(corner_positions(parts[static_cast<std::size_t>(k)]) == corner_positions(expected));
    }
  }
}

TEST_CASE("components: an empty mesh has no part", "[components]") {
  CHECK(connected_components(Mesh{}).empty());
  Mesh only_points;
  only_points.add_vertex(Vec3(0, 0, 0));
  CHECK(connected_components(std::move(only_points)).empty());
}
