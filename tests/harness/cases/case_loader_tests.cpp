// Case files (DESIGN.md section 9, a contract): the built-in cases load and give valid solids, defaults
// are applied, and every kind of bad input is one error line naming the file and the key path.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "harness/cases/case_library.h"
#include "harness/cases/case_loader.h"
#include "harness/cases/case_mesh.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <string>

#ifndef SHATTER_SOURCE_DIR
#error "tests need SHATTER_SOURCE_DIR (a compile definition of the test target)"
#endif

#include <unistd.h>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

const std::string box_mesh = R"("mesh": {"box": {"size": [1, 1, 1]}})";

/// A fresh folder for this test's files (per process: ctest runs test cases side by side).
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shatter_case_tests_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Parses `text` as if read from `<scratch>/x.json`.
Result<Case> parse(const std::string& text) { return parse_case(text, scratch("parse") / "x.json"); }

/// Checks that `text` is refused with one line naming the file and containing every `part`.
void require_error(const std::string& text, std::initializer_list<std::string> parts) {
  const Result<Case> c = parse(text);
  INFO(text);
  REQUIRE_FALSE(c.ok());
  const std::string& message = c.error().message;
  INFO(message);
  CHECK(message.find('\n') == std::string::npos);
  CHECK_THAT(message, Catch::StartsWith((scratch("parse") / "x.json").string() + ": "));
  for (const std::string& part : parts) CHECK_THAT(message, Catch::Contains(part));
}

}  // namespace

TEST_CASE("cases: every built-in case loads and its solid validates", "[cases]") {
  const std::vector<std::string> names = {"cantilever", "column", "fixed-beam", "wall", "tower", "elephant"};
  for (const std::string& name : names) {
    SECTION(name) {
      const fs::path path = fs::path(SHATTER_SOURCE_DIR) / "cases" / (name + ".json");
      if (name == "elephant" && !test::have_meshes()) return;
      const Result<Case> c = load_case(path);
      INFO((c.ok() ? std::string() : c.error().message));
      REQUIRE(c.ok());
      CHECK(c->name == name);
      CHECK_FALSE(c->description.empty());
      CHECK_FALSE(c->anchors.empty());
      const Result<Solid> solid = build_case_solid(*c);
      INFO((solid.ok() ? std::string() : solid.error().message));
      REQUIRE(solid.ok());
      CHECK(solid->mass.volume > 0.0);
      // Every anchor touches the solid and every impact is at a frame the run reaches.
      const Aabb bounds = bounding_box(solid->mesh);
      for (const Aabb& a : c->anchors)
        CHECK(((a.min.array() <= bounds.max.array()).all() && (a.max.array() >= bounds.min.array()).all()));
      for (const ImpactEvent& e : c->impacts) CHECK(e.frame < c->frames);
    }
  }
}

TEST_CASE("cases: the built-in cases have the documented geometry", "[cases]") {
  const fs::path dir = fs::path(SHATTER_SOURCE_DIR) / "cases";
  const Result<Case> cantilever = load_case(dir / "cantilever.json");
  REQUIRE(cantilever.ok());
  REQUIRE(cantilever->prefracture.explicit_planes());
  REQUIRE(cantilever->prefracture.planes.size() == 7);
  CHECK(cantilever->prefracture.planes.front().point.x() == 0.5);
  CHECK(cantilever->prefracture.planes.back().point.x() == 3.5);
  CHECK(cantilever->stress.model == "von-mises");
  CHECK(cantilever->anchors.front().max.x() == 0.001);

  const Result<Case> wall = load_case(dir / "wall.json");
  REQUIRE(wall.ok());
  CHECK_FALSE(wall->prefracture.explicit_planes());
  CHECK(wall->prefracture.fracturer == "plane-slice");
  CHECK(wall->prefracture.fragments == 40);
  CHECK(wall->impacts.size() == 1);

  if (!test::have_meshes()) return;
  const Result<Case> elephant = load_case(dir / "elephant.json");
  REQUIRE(elephant.ok());
  const Result<Solid> solid = build_case_solid(*elephant);
  REQUIRE(solid.ok());
  const Aabb box = bounding_box(solid->mesh);
  CHECK(box.min.z() == Approx(0.0).margin(1e-9));
  CHECK(box.max.z() == Approx(2.0).margin(1e-9));
}

TEST_CASE("cases: the defaults are applied", "[cases]") {
  const Result<Case> c = parse("{" + box_mesh + "}");
  REQUIRE(c.ok());
  CHECK(c->name == "x");
  CHECK(c->description.empty());
  CHECK(std::holds_alternative<BoxSpec>(c->mesh));
  CHECK(std::get<BoxSpec>(c->mesh).center == Vec3::Zero());
  CHECK(c->material.density == 2400.0);
  CHECK(c->material.young_modulus == 3e10);
  CHECK(c->material.poisson_ratio == 0.2);
  CHECK(c->material.tensile_strength == 3e6);
  CHECK(c->material.compressive_strength == 3e7);
  CHECK(c->material.shear_strength == 6e6);
  CHECK(c->gravity == Vec3(0, 0, -9.81));
  CHECK(c->anchors.empty());
  CHECK(c->prefracture.fracturer == "plane-slice");
  CHECK(c->prefracture.fragments == 10);
  CHECK(c->prefracture.seed == 1);
  CHECK_FALSE(c->prefracture.explicit_planes());
  CHECK(c->impacts.empty());
  CHECK(c->runtime.fracturer == "voronoi");
  CHECK(c->runtime.fragments == 10);
  CHECK(c->stress.model == "von-mises");
  CHECK(c->stress.settings.empty());
  CHECK(c->prefracture.settings.empty());
  CHECK(c->runtime.settings.empty());
  CHECK(c->frames == 300);
  CHECK(c->budget_ms == 33.3);
  CHECK(c->grid.prefracture == std::vector<int>{10, 20, 30, 40, 50, 60, 70, 80, 90, 100});
  CHECK(c->grid.runtime == std::vector<int>{5, 10, 15, 20, 25});
  CHECK(c->needs.names() == std::vector<std::string>{"fragments", "bonds", "stress", "colliders", "physics"});

  const Result<Case> partial = parse("{" + box_mesh + R"(, "material": {"density": 7850},
      "impacts": [{"frame": 0, "point": [0, 0, 0], "direction": [0, 0, -2], "impulse": 1}],
      "stress": {"model": "tresca", "settings": {"tolerance": 1e-9}}, "needs": ["bonds", "stress"]})");
  REQUIRE(partial.ok());
  CHECK(partial->material.density == 7850.0);
  CHECK(partial->material.young_modulus == 3e10);
  REQUIRE(partial->impacts.size() == 1);
  CHECK(partial->impacts[0].impact.direction == Vec3(0, 0, -1));
  CHECK(partial->impacts[0].impact.radius == 0.0);
  REQUIRE(partial->stress.settings.size() == 1);
  CHECK(std::get<double>(partial->stress.settings.at("tolerance")) == 1e-9);
  CHECK(partial->needs.names() == std::vector<std::string>{"bonds", "stress"});
}

TEST_CASE("cases: unknown keys are errors naming the key path", "[cases]") {
  require_error("{" + box_mesh + R"(, "colour": "red"})", {": colour: unknown key", "allowed:"});
  require_error("{" + box_mesh + R"(, "material": {"densty": 1}})", {": material.densty: unknown key"});
  require_error(R"({"mesh": {"box": {"size": [1, 1, 1], "radius": 2}}})", {": mesh.box.radius: unknown key"});
  require_error("{" + box_mesh + R"(, "impacts": [{"frame": 1, "point": [0, 0, 0], "direction": [1, 0, 0],
      "impulse": 1, "mass": 3}]})", {": impacts[0].mass: unknown key"});
  require_error("{" + box_mesh + R"(, "anchors": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1], "mid": 0}}]})",
                {": anchors[0].box.mid: unknown key"});
}

TEST_CASE("cases: wrong types are errors naming the key and the expected type", "[cases]") {
  require_error("{" + box_mesh + R"(, "frames": "many"})", {": frames: expected an integer, got a string"});
  require_error("{" + box_mesh + R"(, "frames": 2.5})", {": frames: expected an integer, got 2.5"});
  require_error("{" + box_mesh + R"(, "gravity": [0, -9.81]})", {": gravity: expected an array of 3 numbers"});
  require_error("{" + box_mesh + R"(, "gravity": [0, 0, "down"]})", {": gravity[2]: expected a number"});
  require_error("{" + box_mesh + R"(, "material": 5})", {": material: expected an object, got 5"});
  require_error("{" + box_mesh + R"(, "prefracture": {"seed": -1}})",
                {": prefracture.seed: expected a non-negative integer"});
  require_error("{" + box_mesh + R"(, "stress": {"model": 3}})", {": stress.model: expected a string"});
  require_error("{" + box_mesh + R"(, "needs": "stress"})", {": needs: expected an array"});
  require_error("[1, 2]", {"expected an object, got an array"});
}

TEST_CASE("cases: values out of range are errors naming the key", "[cases]") {
  require_error("{" + box_mesh + R"(, "material": {"density": -3}})", {": material.density: must be in [0.1, 100000] kg/m^3, got -3"});
  require_error("{" + box_mesh + R"(, "material": {"poisson_ratio": 0.5}})",
                {": material.poisson_ratio: must be in [0, 0.5), got 0.5"});
  require_error("{" + box_mesh + R"(, "prefracture": {"planes": [{"point": [0, 0, 0], "normal": [0, 0, 0]}]}})",
                {": prefracture.planes[0].normal: must be a non-zero vector"});
  require_error("{" + box_mesh + R"(, "prefracture": {"planes": []}})",
                {": prefracture.planes: must list at least one"});
  require_error("{" + box_mesh + R"(, "anchors": [{"box": {"min": [0, 0, 2], "max": [1, 1, 1]}}]})",
                {": anchors[0].box: min must be <= max"});
  require_error("{" + box_mesh + R"(, "frames": 10, "impacts": [{"frame": 10, "point": [0, 0, 0],
      "direction": [1, 0, 0], "impulse": 1}]})", {": impacts[0].frame: must be <= 9, got 10"});
  require_error("{" + box_mesh + R"(, "impacts": [{"frame": 1, "point": [0, 0, 0], "direction": [1, 0, 0],
      "impulse": -1}]})", {": impacts[0].impulse: must be in [0, 1e+09] N s, got -1"});
  require_error("{" + box_mesh + R"(, "impacts": [{"frame": 1, "point": [0, 0, 0], "impulse": 1}]})",
                {": impacts[0].direction: missing required key"});
  require_error("{" + box_mesh + R"(, "frames": 0})", {": frames: must be >= 1, got 0"});
  require_error("{" + box_mesh + R"(, "budget_ms": 0})", {": budget_ms: must be > 0, got 0"});
  require_error("{" + box_mesh + R"(, "grid": {"runtime": [5, 0]}})", {": grid.runtime[1]: must be >= 1, got 0"});
  require_error("{" + box_mesh + R"(, "needs": ["stress", "sound"]})", {": needs[1]: unknown need \"sound\""});
  require_error("{" + box_mesh + R"(, "needs": ["stress", "stress"]})", {": needs[1]: duplicate \"stress\""});
  require_error(R"({"mesh": {"torus": {"major_radius": 1, "minor_radius": 1}}})",
                {": mesh.torus.minor_radius: must be <"});
  require_error(R"({"mesh": {"sphere": {"radius": 1, "segments": 2}}})",
                {": mesh.sphere.segments: must be >= 3, got 2"});
  require_error(R"({"mesh": {"box": {"size": [1, 0, 1]}}})", {": mesh.box.size[1]: must be in [1e-06, 1e+06] m, got 0"});
}

TEST_CASE("cases: counts past the documented limits are refused naming the key and the limit", "[cases][limits]") {
  require_error("{" + box_mesh + R"(, "frames": 100001})", {": frames: must be <= 100000, got 100001"});
  REQUIRE(parse("{" + box_mesh + R"(, "frames": 100000})").ok());
  require_error(R"({"mesh": {"sphere": {"radius": 1, "segments": 5000}}})",
                {": mesh.sphere.segments: must be <= 4096, got 5000"});
  require_error(R"({"mesh": {"sphere": {"radius": 1, "segments": 4096, "rings": 4096}}})",
                {": mesh.sphere: segments x rings = 4096 x 4096 make 33546240 triangles, which exceeds the limit of "
                 "10000000 triangles per mesh"});
  require_error(
      R"({"mesh": {"torus": {"major_radius": 1, "minor_radius": 0.5, "major_segments": 4096,
      "minor_segments": 2000}}})",
      {": mesh.torus: major_segments x minor_segments = 4096 x 2000 make 16384000 triangles", "limit of 10000000"});
  REQUIRE(parse(R"({"mesh": {"sphere": {"radius": 1, "segments": 4096, "rings": 1000}}})").ok());
  require_error("{" + box_mesh + R"(, "debris": {"per_impact": 100001}})",
                {": debris.per_impact: must be <= 100000, got 100001"});
  require_error("{" + box_mesh + R"(, "grid": {"prefracture": [100000], "runtime": [10, 11]}})",
                {": grid: cell 100000 x 11 can make 1100000 runtime pieces, which exceeds the limit of 1000000"});
  REQUIRE(parse("{" + box_mesh + R"(, "grid": {"prefracture": [100000], "runtime": [10]}})").ok());

  // Lists past their limits: 101 x 100 grid cells, 1001 impacts, 1001 planes, a prism of 100001 corners.
  const auto counts = [](int from, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) {
      if (i > 0) out += ",";
      out += std::to_string(from + i);
    }
    return "[" + out + "]";
  };
  require_error(
      "{" + box_mesh + R"(, "grid": {"prefracture": )" + counts(1, 101) + R"(, "runtime": )" + counts(1, 100) + "}}",
      {": grid: 101 x 100 = 10100 cells exceed the limit of 10000 cells per grid"});
  REQUIRE(parse("{" + box_mesh + R"(, "grid": {"prefracture": )" + counts(1, 100) + R"(, "runtime": )" +
                counts(1, 100) + "}}")
              .ok());
  const auto repeat = [](const std::string& item, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) {
      if (i > 0) out += ",";
      out += item;
    }
    return "[" + out + "]";
  };
  const std::string impact = R"({"frame": 1, "point": [0, 0, 0], "direction": [1, 0, 0], "impulse": 1})";
  require_error("{" + box_mesh + R"(, "impacts": )" + repeat(impact, 1001) + "}",
                {": impacts: 1001 impacts exceed the limit of 1000 impacts per case"});
  REQUIRE(parse("{" + box_mesh + R"(, "impacts": )" + repeat(impact, 1000) + "}").ok());
  const std::string plane = R"({"point": [0, 0, 0], "normal": [1, 0, 0]})";
  require_error("{" + box_mesh + R"(, "prefracture": {"planes": )" + repeat(plane, 1001) + "}}",
                {": prefracture.planes: 1001 planes exceed the limit of 1000 planes"});
  std::string outline;
  for (int i = 0; i < 100001; ++i) outline += fmt::format("{}[{}, {}]", i ? "," : "", i, i % 2);
  require_error(R"({"mesh": {"prism": {"outline": [)" + outline + "]}}}",
                {": mesh.prism: 100001 corners (outline and holes) exceed the limit of 100000 corners per prism"});
}

TEST_CASE("cases: a case file larger than the limit is refused before it is read", "[cases][limits]") {
  const fs::path file = scratch("large") / "large.json";
  { std::ofstream(file) << "{" << box_mesh << "}"; }
  REQUIRE(load_case(file).ok());
  fs::resize_file(file, (16u << 20) + 1);  // sparse: nothing written past the text
  const Result<Case> c = load_case(file);
  REQUIRE_FALSE(c.ok());
  CHECK(c.error().message ==
        file.string() + ": larger than the limit of 16777216 bytes per case file (the file has 16777217 bytes)");
  fs::remove(file);
}

TEST_CASE("cases: structural errors name the key", "[cases]") {
  require_error(R"({"name": "m"})", {": mesh: missing required key"});
  require_error(R"({"mesh": {}})", {": mesh: expected one of box, sphere"});
  require_error(R"({"mesh": {"box": {"size": [1, 1, 1]}, "sphere": {"radius": 1}}})",
                {": mesh: \"box\" and \"sphere\" are exclusive"});
  require_error(R"({"mesh": {"box": {"size": [1, 1, 1]}, "scale": 2}})", {": mesh.scale: only allowed with \"file\""});
  require_error(R"({"mesh": {"file": "nope.off"}})", {": mesh.file: mesh file \"nope.off\" not found"});
  require_error(R"({"mesh": {"file": "mesh.xyz"}})", {": mesh.file: expected a mesh file (.off, .obj, .gltf, .glb"});
  require_error("{" + box_mesh + R"(, "prefracture": {"fracturer": "voronoi",
      "planes": [{"point": [0, 0, 0], "normal": [1, 0, 0]}]}})",
                {": prefracture: \"fracturer\" and \"planes\" are exclusive"});
  require_error("{" + box_mesh + R"(, "material": {"density": 1, "density": 2}})", {"key \"density\" appears twice"});
}

TEST_CASE("cases: malformed JSON names the file, line and column", "[cases]") {
  require_error("{\n  \"mesh\": {\"box\": {\"size\": [1, 1, 1]}},\n  \"frames\": 30,,\n}",
                {": line 3, column 16: invalid JSON:"});
  require_error("{\n  \"mesh\": ", {": line 2, column", "invalid JSON"});
  require_error("", {"invalid JSON"});
  require_error("{\n  \"frames\": 1e400}", {": line 2, column 13: invalid JSON: number overflow"});
}

TEST_CASE("cases: a mesh file is resolved against the case folder and transformed", "[cases]") {
  const fs::path dir = scratch("mesh_file");
  fs::create_directories(dir / "meshes");
  fs::create_directories(dir / "sub");
  REQUIRE(write_off(make_box(Vec3(1, 2, 3)), dir / "meshes" / "b.off").ok());
  const std::string text =
      R"({"mesh": {"file": "../meshes/b.off", "scale": 2, "rotate": [0, 0, 90], "translate": [0, 0, 3]}})";
  const Result<Case> c = parse_case(text, dir / "sub" / "c.json");
  INFO((c.ok() ? std::string() : c.error().message));
  REQUIRE(c.ok());
  const Result<Solid> solid = build_case_solid(*c);
  REQUIRE(solid.ok());
  // Size (2, 4, 6) after scaling; a quarter turn about z swaps x and y exactly.
  const Aabb box = bounding_box(solid->mesh);
  CHECK(box.min == Vec3(-2, -1, 0));
  CHECK(box.max == Vec3(2, 1, 6));
  CHECK(solid->mass.volume == Approx(48.0));
}

TEST_CASE("cases: every primitive builds a valid solid", "[cases]") {
  for (const std::string mesh : {R"({"sphere": {"radius": 1, "segments": 12, "rings": 6}})",
                                 R"({"cylinder": {"radius": 1, "height": 2, "center": [0, 0, 1]}})",
                                 R"({"torus": {"major_radius": 1, "minor_radius": 0.3, "major_segments": 16}})",
                                 R"({"tube": {"inner_radius": 0.5, "outer_radius": 1, "height": 2, "segments": 8}})"}) {
    const Result<Case> c = parse(R"({"mesh": )" + mesh + "}");
    INFO(mesh);
    REQUIRE(c.ok());
    const Result<Solid> solid = build_case_solid(*c);
    REQUIRE(solid.ok());
    CHECK(solid->mass.volume > 0.0);
  }
}

TEST_CASE("cases: find_case finds built-in cases by name and files by path", "[cases]") {
  const Result<Case> by_name = find_case("cantilever");
  INFO((by_name.ok() ? std::string() : by_name.error().message));
  REQUIRE(by_name.ok());
  CHECK(by_name->name == "cantilever");

  const Result<Case> by_path = find_case((fs::path(SHATTER_SOURCE_DIR) / "cases" / "column.json").string());
  REQUIRE(by_path.ok());
  CHECK(by_path->name == "column");

  const Result<Case> unknown = find_case("no-such-case");
  REQUIRE_FALSE(unknown.ok());
  CHECK_THAT(unknown.error().message,
             Catch::Contains("unknown case \"no-such-case\"") && Catch::Contains("cantilever"));
  CHECK_FALSE(find_case("missing/dir/case.json").ok());

  const std::vector<BuiltinCase> cases = list_builtin_cases();
  for (const std::string name : {"cantilever", "column", "fixed-beam", "wall", "tower", "elephant"}) {
    const auto it = std::find_if(cases.begin(), cases.end(), [&](const BuiltinCase& b) { return b.name == name; });
    REQUIRE(it != cases.end());
    CHECK_FALSE(it->description.empty());
  }
}

TEST_CASE("cases: the wall's window is a real opening", "[cases]") {
  auto c = shatter::find_case("wall");
  REQUIRE(c.ok());
  auto solid = shatter::build_case_solid(*c);
  REQUIRE(solid.ok());
  // (4 x 3 - 1 x 1.2) m^2 of elevation, 0.3 m deep.
  CHECK(solid->mass.volume == Approx((4.0 * 3.0 - 1.0 * 1.2) * 0.3).epsilon(1e-12));
  // Its surface: both faces, the outer rim and the window's reveal.
  CHECK(solid->area == Approx(2 * (12.0 - 1.2) + 0.3 * (2 * 4 + 2 * 3) + 0.3 * (2 * 1.0 + 2 * 1.2)).epsilon(1e-12));
  CHECK_FALSE(solid->report.flipped);
}

TEST_CASE("cases: a prism whose outline crosses itself is refused", "[cases]") {
  const std::string text = R"({"mesh": {"prism": {"outline": [[0, 0], [1, 1], [1, 0], [0, 1]], "depth": 1}}})";
  auto c = shatter::parse_case(text, "bowtie.json");
  REQUIRE(c.ok());
  auto solid = shatter::build_case_solid(*c);
  REQUIRE_FALSE(solid.ok());
  CHECK_THAT(solid.error().message, Catch::Contains("prism"));
}

TEST_CASE("cases: colliders.vertex_budget is read, 0 by default, and checked", "[cases][colliders]") {
  const Result<Case> plain = parse("{" + box_mesh + "}");
  REQUIRE(plain.ok());
  CHECK(plain->colliders.vertex_budget == 0);
  const Result<Case> budget = parse("{" + box_mesh + R"(, "colliders": {"vertex_budget": 24}})");
  REQUIRE(budget.ok());
  CHECK(budget->colliders.vertex_budget == 24);
  require_error("{" + box_mesh + R"(, "colliders": {"vertex_budget": 3}})", {"colliders.vertex_budget", ">= 4"});
  require_error("{" + box_mesh + R"(, "colliders": {"vertex_budget": 257}})", {"colliders.vertex_budget", "<= 256"});
  require_error("{" + box_mesh + R"(, "colliders": {"budget": 8}})", {"colliders.budget"});
}
