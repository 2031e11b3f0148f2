// The `fracture` and `list` commands: the JSON contract, the written files, and the exit-2 contract on
// bad input (one line on stderr naming the problem, no output files).

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "tests/support/cli_runner.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "shatter_cli_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void require_bad_input(const test::CliRun& run, const std::string& mentions) {
  CHECK(run.exit_code == 2);
  CHECK(test::line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains(mentions, Catch::CaseSensitive::No));
  CHECK(run.out.empty());
}

}  // namespace

TEST_CASE("cli: fracture prints the contract JSON and writes the fragments", "[cli]") {
  const fs::path dir = scratch("fracture_ok");
  REQUIRE(write_off(make_sphere(1.0, 16, 8), dir / "sphere.off").ok());
  const auto run = test::run_cli("fracture --mesh " + (dir / "sphere.off").string() +
                                 " --algo plane-slice --fragments 6 --seed 3 --out " + (dir / "frags").string());
  REQUIRE(run.exit_code == 0);
  const auto j = nlohmann::json::parse(run.out);
  CHECK(j.at("algorithm") == "plane-slice");
  const int n = j.at("fragments");
  CHECK(n >= 6);
  CHECK(j.at("time_ms").get<double>() >= 0.0);
  CHECK(j.at("input").at("triangles").get<int>() > 0);
  CHECK(j.at("input").at("volume").get<double>() > 0.0);
  CHECK(j.at("input").at("area").get<double>() > 0.0);
  const auto& m = j.at("metrics");
  CHECK(m.at("volume_error").get<double>() <= 1e-9);
  CHECK(m.at("all_closed").get<bool>());
  CHECK(m.at("partition_error").get<double>() == 0.0);
  CHECK(m.at("area_error").get<double>() <= 1e-9);
  CHECK(m.at("min_fragment_volume").get<double>() > 0.0);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir / "frags")) files += e.path().extension() == ".obj";
  CHECK(files == n);
  CHECK(fs::exists(dir / "frags" / "fragment_000.obj"));
  CHECK(fs::exists(dir / "frags" / "fragments.glb"));  // written with or without attributes
  auto back = read_obj(dir / "frags" / "fragment_000.obj");
  REQUIRE(back.ok());
  CHECK(back->triangle_count() > 0);
}

TEST_CASE("cli: fracture reads a textured glTF and writes materials, UVs and a glTF of the fragments", "[cli][assets]") {
  const fs::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  REQUIRE(fs::exists(box));  // assimp-testmodels (scripts/install-deps)
  const fs::path dir = scratch("fracture_glb");
  const auto run = test::run_cli("fracture --mesh " + box.string() + " --algo plane-slice --fragments 4 --seed 1 --out " +
                                 (dir / "frags").string());
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto j = nlohmann::json::parse(run.out);
  CHECK(j.at("metrics").at("all_closed").get<bool>());
  CHECK(j.at("metrics").at("volume_error").get<double>() <= 1e-9);  // the box is 1 m^3, split exactly
  // The attribute error: the texture mapping reproduced to round-off, every face in its material.
  const auto& a = j.at("metrics").at("attributes");
  REQUIRE(a.is_object());
  CHECK(a.at("samples").get<int>() == 1000);
  CHECK(a.at("uv_error").get<double>() < 1e-12);
  CHECK(a.at("normal_error").get<double>() < 1e-12);
  CHECK(a.at("cap_normal_error").get<double>() < 1e-12);
  CHECK(a.at("material_errors").get<int>() == 0);
  CHECK(fs::exists(dir / "frags" / "fragments.glb"));
  REQUIRE(fs::exists(dir / "frags" / "fragments.mtl"));
  // Every fragment names the shared library; cut faces carry the interior material, the rest the box's.
  const Result<Mesh> back = read_obj(dir / "frags" / "fragment_000.obj");
  REQUIRE(back.ok());
  CHECK(back->attributes.layout.normals);
  CHECK(back->attributes.layout.uv_sets == 1);
  bool interior = false, texture = false;
  for (std::size_t f = 0; f < back->triangles.size(); ++f) {
    const std::string& name = back->attributes.slots[static_cast<std::size_t>(back->attributes.materials[f])].name;
    CHECK(name == (back->tags[f] == FaceTag::cut ? "interior" : "Texture"));
    interior = interior || name == "interior";
    texture = texture || name == "Texture";
  }
  CHECK(interior);
  CHECK(texture);
}

TEST_CASE("cli: without --out nothing is written", "[cli]") {
  const fs::path dir = scratch("fracture_no_out");
  REQUIRE(write_off(make_box(Vec3(1, 1, 1)), dir / "box.off").ok());
  const auto run = test::run_cli("fracture --mesh " + (dir / "box.off").string() + " --fragments 3");
  CHECK(run.exit_code == 0);
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  CHECK(entries == 1);
}

TEST_CASE("cli: list names the fracturers", "[cli]") {
  const auto run = test::run_cli("list");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Catch::Contains("plane-slice"));
  CHECK_THAT(run.out, Catch::Contains("cgal-clip"));
}

TEST_CASE("cli: bad input exits 2 with one line and no output files", "[cli]") {
  const fs::path dir = scratch("fracture_bad");
  const fs::path out = dir / "frags";
  const std::string out_flag = " --out " + out.string();

  SECTION("a non-closed mesh under --no-repair") {
    if (!test::have_meshes()) return;
    require_bad_input(test::run_cli("fracture --mesh " + (test::mesh_dir() / "mushroom.off").string() +
                                    " --fragments 5 --no-repair" + out_flag),
                      "not closed");
  }
  SECTION("an open sheet, which no repair makes a solid") {
    if (!test::have_meshes()) return;
    require_bad_input(test::run_cli("fracture --mesh " + (test::mesh_dir() / "quad.off").string() +
                                    " --fragments 5" + out_flag),
                      "quad.off");
  }
  SECTION("a truncated file") {
    REQUIRE(write_off(make_sphere(1.0, 16, 8), dir / "whole.off").ok());
    const std::string text = test::slurp(dir / "whole.off");
    std::ofstream(dir / "cut.off") << text.substr(0, text.size() / 2);
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "cut.off").string() + " --fragments 5" + out_flag),
                      "cut.off");
  }
  SECTION("NaN coordinates") {
    std::ofstream(dir / "nan.off") << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "nan.off").string() + " --fragments 5" + out_flag),
                      "finite");
  }
  SECTION("zero fragments") {
    REQUIRE(write_off(make_box(Vec3(1, 1, 1)), dir / "box.off").ok());
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "box.off").string() + " --fragments 0" + out_flag),
                      "fragments");
  }
  SECTION("an unknown fracturer") {
    REQUIRE(write_off(make_box(Vec3(1, 1, 1)), dir / "box.off").ok());
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "box.off").string() + " --algo nope" + out_flag),
                      "plane-slice");
  }
  SECTION("a missing file") {
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "absent.off").string() + out_flag), "absent.off");
  }
  SECTION("an impact with two coordinates") {
    REQUIRE(write_off(make_box(Vec3(1, 1, 1)), dir / "box.off").ok());
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "box.off").string() + " --impact 0,0" + out_flag),
                      "--impact");
  }
  SECTION("a negative impact radius") {
    REQUIRE(write_off(make_box(Vec3(1, 1, 1)), dir / "box.off").ok());
    require_bad_input(test::run_cli("fracture --mesh " + (dir / "box.off").string() +
                                    " --impact 0,0,0 --radius -1" + out_flag),
                      "--radius");
  }
  SECTION("an unknown flag") {
    require_bad_input(test::run_cli("fracture --mesh x.off --frobnicate 3"), "frobnicate");
  }
  CHECK_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().rfind(".frags", 0) != 0);
}

TEST_CASE("cli: a self-intersecting mesh is refused under --no-repair by every fracturer, and repaired without it", "[cli]") {
  if (!test::have_meshes()) return;
  const auto cow = test::mesh_dir() / "cow.off";
  REQUIRE(std::filesystem::exists(cow));
  const auto out = std::filesystem::temp_directory_path() / "shatter_cli_cow_out";
  std::filesystem::remove_all(out);
  for (const char* algo : {"plane-slice", "voronoi", "fem-lite", "cgal-clip"}) {
    const auto r = shatter::test::run_cli(std::string("fracture --mesh ") + cow.string() + " --algo " + algo +
                                          " --fragments 5 --no-repair --out " + out.string());
    INFO(algo << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(shatter::test::line_count(r.err) == 1);
    CHECK(r.err.find("cow.off") != std::string::npos);
    CHECK(r.err.find("intersect") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  const auto repaired = shatter::test::run_cli(std::string("fracture --mesh ") + cow.string() + " --algo voronoi --fragments 5");
  INFO(repaired.err);
  REQUIRE(repaired.exit_code == 0);
  const auto j = nlohmann::json::parse(repaired.out);
  CHECK(j.at("input").at("repairs").at("self_intersections").get<int>() > 0);
  CHECK(j.at("input").at("repairs").at("self_intersection_fix") != "");
  CHECK(j.at("metrics").at("all_closed").get<bool>());
}
