// Inputs the fuzzers found (fuzz/, scripts/fuzz), kept as tests. Each is also in the fuzzer's seed
// corpus, so every fuzz run replays it under AddressSanitizer and UndefinedBehaviorSanitizer.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/cap_triangulator.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/cases/case_loader.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

using namespace shatter;

TEST_CASE("fuzz regression: a cap a few subnormals wide triangulates without overflow", "[plane-slice]") {
  // plane_slice_fuzzer found a plane through (4.9e-311, 0, 1.3e-317) with a normal of ~1e232 cutting
  // the corner of a tetrahedron: the cap's points were ~1e-311 apart, 1 / size was inf, and the point
  // ordering converted inf * 0 to an integer (undefined behaviour). The cap must triangulate, or be
  // refused cleanly, for any width.
  const std::vector<Vec2> points = {{0.0, 0.0}, {1e-310, 0.0}, {0.0, 1e-310}, {3e-311, 3e-311}};
  const std::vector<CapEdge> edges = {{0, 1}, {1, 2}, {2, 0}};
  const CapTriangulation cap = triangulate_cap(points, edges);
  // Scaled by a power of two before the predicates (exact), the cap is the one triangle it is.
  REQUIRE(cap.ok);
  REQUIRE(cap.triangles.size() == 1);
  const Triangle& t = cap.triangles[0];  // (0, 1, 2) up to rotation: counter-clockwise, as the outline
  CHECK(((t == Triangle{0, 1, 2}) || (t == Triangle{1, 2, 0}) || (t == Triangle{2, 0, 1})));
  // The same at the other end of the range, and mirrored: the orientation is kept.
  const std::vector<Vec2> huge = {{0.0, 0.0}, {1e306, 0.0}, {0.0, 1e306}};
  const CapTriangulation big = triangulate_cap(huge, edges);
  REQUIRE(big.ok);
  CHECK(big.triangles.size() == 1);
  const std::vector<CapEdge> clockwise = {{0, 2}, {2, 1}, {1, 0}};
  CHECK(triangulate_cap(points, clockwise).triangles.empty());  // a hole with no outline around it

  // The input itself: the fuzzer's layout (mode byte, plane point, plane normal).
  const auto path = std::filesystem::path(SHATTER_SOURCE_DIR) / "tests" / "fixtures" / "fuzz" / "plane_slice_subnormal_cap.bin";
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() >= 49);
  Plane plane;
  for (int i = 0; i < 3; ++i) std::memcpy(&plane.point[i], bytes.data() + 1 + 8 * i, 8);
  for (int i = 0; i < 3; ++i) std::memcpy(&plane.normal[i], bytes.data() + 25 + 8 * i, 8);
  Mesh tet;
  tet.add_vertex({0.0, 0.0, 0.0});
  tet.add_vertex({1.0, 0.0, 0.0});
  tet.add_vertex({0.0, 1.0, 0.0});
  tet.add_vertex({0.0, 0.0, 1.0});
  tet.add_triangle(0, 2, 1, FaceTag::surface);
  tet.add_triangle(0, 1, 3, FaceTag::surface);
  tet.add_triangle(0, 3, 2, FaceTag::surface);
  tet.add_triangle(1, 2, 3, FaceTag::surface);
  const double volume = signed_volume(tet);
  const Plane planes[] = {plane};
  const auto fragments = PlaneSliceFracturer().fracture_by_planes(tet, planes);
  if (!fragments) return;  // refusing the plane is a clean outcome
  double total = 0.0;
  for (const Fragment& f : *fragments) {
    CHECK(all_finite(f.mesh));
    CHECK(is_closed_and_oriented(f.mesh));
    total += signed_volume(f.mesh);
  }
  CHECK(std::abs(total - volume) <= 1e-9 * volume);
}

TEST_CASE("fuzz regression: a case key holding a newline is named on one line", "[case-loader]") {
  // case_loader_fuzzer found {"\n": "C"}: the unknown key was quoted as it is, so the message broke
  // across two lines. Every case loader message now writes control characters as escapes.
  const auto path = std::filesystem::path(SHATTER_SOURCE_DIR) / "tests" / "fixtures" / "fuzz" / "case_control_character_key.json";
  const Result<Case> from_file = load_case(path);
  REQUIRE_FALSE(from_file);
  CHECK(from_file.error().message.find('\n') == std::string::npos);
  CHECK_THAT(from_file.error().message, Catch::Contains(": \\n: unknown key"));
  // Values too: a fracturer name with a tab and a bell character.
  const Result<Case> value = parse_case(R"({"mesh": {"box": [1, 1, 1]}, "runtime": {"fracturer": "a\tb\u0007"}})", "v.json");
  REQUIRE_FALSE(value);
  CHECK(value.error().message.find_first_of("\t\a\n") == std::string::npos);
}

TEST_CASE("fuzz regression: an OFF polygon face with a point 1e174 away is refused, not walked off the cap",
          "[hostile]") {
  // off_reader_fuzzer found quad faces of a cube whose one vertex lies at y ~ 1e174 (seed 1): the
  // face's constrained Delaunay triangulation (cap_triangulator.cpp) indexed triangle -1 in one input
  // (UndefinedBehaviorSanitizer: pointer overflow) and looped forever in another, because the exact
  // predicates under- and overflow at such a spread of coordinates. A polygon face with a corner
  // beyond the representable range (which a solid must keep anyway) is now refused before it is
  // triangulated, and the walk and the recovery stop with an error if their orientations disagree.
  for (const char* name : {"off_polygon_face_far_point.off", "off_polygon_face_far_point_loop.off"}) {
    INFO(name);
    const auto path = std::filesystem::path(SHATTER_SOURCE_DIR) / "tests" / "fixtures" / "fuzz" / name;
    REQUIRE(std::filesystem::exists(path));
    const Result<Mesh> mesh = read_mesh(path);
    REQUIRE_FALSE(mesh);
    CHECK(mesh.error().message.find('\n') == std::string::npos);
    CHECK_THAT(mesh.error().message, Catch::StartsWith(path.string()) && Catch::Contains("representable range"));
  }
}
