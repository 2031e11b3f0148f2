// A mesh that is not a solid, through the command line: repaired by default and reported in
// `input.repairs` (fracture and grid), refused with the acceptance rule's reason under `--no-repair`
// or `"repair": false`, and a mesh that encloses nothing refused in one line.

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "shatter_cli_repair_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// A 2 x 1 x 1 box without its top face (z = max): the two triangles whose corners all lie on top are
/// dropped. Volume 2, the missing face's area 2.
Mesh open_box() {
  Mesh box = make_box(Vec3(2, 1, 1), Vec3(0, 0, 0.5));
  Mesh out;
  out.vertices = box.vertices;
  for (std::size_t t = 0; t < box.triangles.size(); ++t) {
    const Triangle& tri = box.triangles[t];
    bool top = true;
    for (const std::int32_t v : tri) top = top && box.vertices[static_cast<std::size_t>(v)].z() == 1.0;
    if (!top) out.add_triangle(tri[0], tri[1], tri[2], FaceTag::surface);
  }
  REQUIRE(out.triangles.size() + 2 == box.triangles.size());
  return out;
}

/// One flat square made of two triangles: a sheet that encloses nothing.
Mesh flat_sheet() {
  Mesh m;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) m.add_vertex(p);
  m.add_triangle(0, 1, 2, FaceTag::surface);
  m.add_triangle(0, 2, 3, FaceTag::surface);
  return m;
}

}  // namespace

TEST_CASE("cli repair: an open box is filled, reported, and fractured like with like", "[cli][repair]") {
  const fs::path dir = scratch("open_box");
  const fs::path mesh = dir / "open_box.off";
  REQUIRE(write_off(open_box(), mesh).ok());
  const auto run = test::run_cli("fracture --mesh " + mesh.string() + " --algo plane-slice --fragments 6 --out " +
                                 (dir / "frags").string());
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto j = nlohmann::json::parse(run.out);
  const auto& input = j.at("input");
  CHECK(input.at("volume").get<double>() == Approx(2.0).epsilon(1e-12));
  const auto& r = input.at("repairs");
  CHECK(r.at("repaired").get<bool>());
  CHECK(r.at("holes_filled").get<int>() == 1);
  CHECK(r.at("hole_area").get<double>() == Approx(2.0).epsilon(1e-12));
  CHECK(r.at("self_intersections").get<int>() == 0);
  CHECK(r.at("shells").get<int>() == 1);
  CHECK(r.at("cavities").get<int>() == 0);
  CHECK(r.at("time_ms").get<double>() >= 0.0);
  // The filled 2 x 1 face is farthest from the input's walls at its centre line: 0.5 (sampled, so at most).
  CHECK(r.at("hausdorff_distance").get<double>() <= 0.5 + 1e-9);
  CHECK(r.at("hausdorff_distance").get<double>() >= 0.4);
  const auto& m = j.at("metrics");
  CHECK(m.at("volume_error").get<double>() <= 1e-9);
  CHECK(m.at("all_closed").get<bool>());
  // Repair faces are compared with repair faces: counting them as the input's surface would make this 0.5.
  CHECK(m.at("area_error").get<double>() <= 1e-9);
  // The filled face is its own group in the fragments' OBJ files.
  bool repair_group = false;
  for (const auto& e : fs::directory_iterator(dir / "frags")) {
    std::ifstream in(e.path());
    std::string line;
    while (std::getline(in, line)) repair_group = repair_group || line == "g repair";
  }
  CHECK(repair_group);
}

TEST_CASE("cli repair: --no-repair refuses an open box with the rule's reason", "[cli][repair]") {
  const fs::path dir = scratch("no_repair");
  const fs::path mesh = dir / "open_box.off";
  REQUIRE(write_off(open_box(), mesh).ok());
  for (const std::string command : {"fracture --mesh " + mesh.string() + " --algo voronoi --fragments 4 --no-repair",
                                    "table --mesh " + mesh.string() + " --fragments 4 --no-repair"}) {
    INFO(command);
    const auto run = test::run_cli(command);
    CHECK(run.exit_code == 2);
    CHECK(test::line_count(run.err) == 1);
    CHECK_THAT(run.err, Catch::Contains("not closed"));
    CHECK_THAT(run.err, Catch::Contains("open_box.off"));
    CHECK(run.out.empty());
  }
}

TEST_CASE("cli repair: a solid is not repaired", "[cli][repair]") {
  const fs::path dir = scratch("solid");
  const fs::path mesh = dir / "sphere.off";
  REQUIRE(write_off(make_sphere(1.0, 16, 8), mesh).ok());
  const auto run = test::run_cli("fracture --mesh " + mesh.string() + " --algo voronoi --fragments 4");
  REQUIRE(run.exit_code == 0);
  const auto r = nlohmann::json::parse(run.out).at("input").at("repairs");
  CHECK_FALSE(r.at("repaired").get<bool>());
  for (const char* key : {"vertices_merged", "faces_removed", "faces_reoriented", "holes_filled", "self_intersections",
                          "sheets_removed", "cavities"})
    CHECK(r.at(key).get<int>() == 0);
  CHECK(r.at("hole_area").get<double>() == 0.0);
  CHECK(r.at("hausdorff_distance").get<double>() == 0.0);
  CHECK(r.at("self_intersection_fix") == "");
  CHECK(r.at("shells").get<int>() == 1);
}

TEST_CASE("cli repair: a flat sheet encloses nothing and is refused in one line", "[cli][repair]") {
  const fs::path dir = scratch("sheet");
  const fs::path mesh = dir / "sheet.off";
  REQUIRE(write_off(flat_sheet(), mesh).ok());
  for (const std::string algo : {"plane-slice", "voronoi", "fem-lite", "cgal-clip"}) {
    const auto run = test::run_cli("fracture --mesh " + mesh.string() + " --algo " + algo + " --fragments 3");
    INFO(algo << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(test::line_count(run.err) == 1);
    CHECK_THAT(run.err, Catch::Contains("sheet.off"));
    CHECK(run.out.empty());
  }
}

TEST_CASE("cli repair: grid reports the repairs of the case's mesh, and \"repair\": false refuses it", "[cli][repair][grid]") {
  const fs::path dir = scratch("grid");
  REQUIRE(write_off(open_box(), dir / "open_box.off").ok());
  const auto write_case = [&](const std::string& name, const std::string& extra) {
    std::ofstream(dir / name) << R"({"name": "open-box", "description": "an open box, repaired",
      "mesh": {"file": "open_box.off")" << extra << R"(},
      "anchors": [{"box": {"min": [-2, -2, -1], "max": [2, 2, 0.01]}}],
      "prefracture": {"fracturer": "voronoi", "fragments": 4, "seed": 1},
      "impacts": [{"frame": 2, "point": [1, 0, 0.5], "direction": [-1, 0, 0], "impulse": 100, "radius": 0.5}],
      "runtime": {"fracturer": "voronoi", "fragments": 3},
      "frames": 5})";
  };
  write_case("repaired.json", "");
  write_case("refused.json", R"(, "repair": false)");
  const std::string common = " --prefracture 4 --runtime 3 --repetitions 1 --no-cache --budget-ms 100000";
  const auto run = test::run_cli("grid --case " + (dir / "repaired.json").string() + common + " --json " +
                                 (dir / "out.json").string());
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  std::ifstream in(dir / "out.json");
  const auto j = nlohmann::json::parse(in);
  CHECK(j.at("input").at("repairs").at("holes_filled").get<int>() == 1);
  CHECK(j.at("input").at("volume").get<double>() == Approx(2.0).epsilon(1e-12));

  for (const std::string refused : {"grid --case " + (dir / "refused.json").string() + common,
                                    "grid --case " + (dir / "repaired.json").string() + common + " --no-repair"}) {
    INFO(refused);
    const auto no = test::run_cli(refused);
    CHECK(no.exit_code == 2);
    CHECK(test::line_count(no.err) == 1);
    CHECK_THAT(no.err, Catch::Contains("not closed"));
  }
}
