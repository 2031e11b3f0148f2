// Hostile solids and invalid results. A closed, consistently oriented mesh can still describe no
// solid (shells that cross, nest with one orientation or face inward inside nothing) or a solid
// with cavities, whose fracture is not supported: every one is refused where solids enter, through
// the library and through every command, in one line that names the shells. Disjoint outward
// shells are one solid whose volume is the sum; a solid read inside out is flipped. A fracture
// result whose own figures are invalid fails its checks. The truths are the primitives' exact
// volumes and the nesting each test builds.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/shell_classification.h"
#include "harness/cases/load_solid.h"
#include "harness/results/cell_checks.h"
#include "harness/metrics/fracture_acceptance.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;

namespace {

/// One shell of a test solid: a mesh and whether its triangles are reversed (an inward shell).
struct Part {
  Mesh mesh;
  bool inward = false;
};

/// The shells as one mesh, in the given order (shell i of the classification is parts[i]).
Mesh combine(const std::vector<Part>& parts) {
  Mesh out;
  for (const Part& part : parts) {
    const auto offset = static_cast<std::int32_t>(out.vertices.size());
    for (const Vec3& p : part.mesh.vertices) out.add_vertex(p);
    for (const Triangle& t : part.mesh.triangles)
      if (part.inward)
        out.add_triangle(t[0] + offset, t[2] + offset, t[1] + offset, FaceTag::surface);
      else
        out.add_triangle(t[0] + offset, t[1] + offset, t[2] + offset, FaceTag::surface);
  }
  return out;
}

Mesh box(double size, const Vec3& center = Vec3::Zero()) { return make_box(Vec3::Constant(size), center); }
Mesh sphere(double radius, const Vec3& center = Vec3::Zero()) { return make_sphere(radius, 24, 12, center); }

/// The error validate_solid gives, or "(valid)".
std::string refusal(Mesh mesh) {
  const Result<ValidationReport> report = validate_solid(mesh, "solid.off");
  return report ? std::string("(valid)") : report.error().message;
}

/// A temporary folder of its own, emptied.
std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("shatter_hostile_solids_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `mesh` as OBJ when `path` ends in .obj, else as OFF; returns the path.
std::string write_mesh(const Mesh& mesh, const std::filesystem::path& path) {
  REQUIRE((path.extension() == ".obj" ? write_obj(mesh, path) : write_off(mesh, path)).ok());
  return path.string();
}

/// Hollow solids: one cavity or several, centred or not, with an island inside a cavity.
std::vector<std::pair<std::string, Mesh>> solids_with_cavities() {
  return {
      {"sphere with a spherical cavity", combine({{sphere(1.0)}, {sphere(0.5), true}})},
      {"box with a box cavity", combine({{box(2.0)}, {box(1.0), true}})},
      {"box with an off-centre spherical cavity", combine({{box(4.0)}, {sphere(0.5, Vec3(1, 0.5, -0.5)), true}})},
      {"box with two cavities", combine({{box(4.0)}, {box(0.5, Vec3(-1, 0, 0)), true}, {box(0.5, Vec3(1, 0, 0)), true}})},
      {"cavity holding an island", combine({{box(4.0)}, {box(2.0), true}, {box(1.0)}})},
  };
}

}  // namespace

TEST_CASE("solids: a solid with cavities is accepted, the classification names the cavity and its shell", "[hostile][solids]") {
  for (const auto& [name, mesh] : solids_with_cavities()) {
    INFO(name);
    const ShellClassification c = classify_shells(mesh);
    CHECK(c.verdict == SolidVerdict::with_cavities);
    CHECK_FALSE(c.inverted);
    CHECK(c.shells[0].container == -1);
    CHECK(c.shells[1].container == 0);  // the first cavity lies in the outer shell
    CHECK(refusal(mesh) == "(valid)");
    CHECK_THAT(c.reason, Contains("shell 1 (") && Contains("inside shell 0 ("));
    CHECK(c.reason.find('\n') == std::string::npos);
  }
  // The volumes are the shells' own: an inward shell's is negative, exactly the box's.
  const ShellClassification c = classify_shells(combine({{box(2.0)}, {box(1.0), true}}));
  REQUIRE(c.shells.size() == 2);
  CHECK(c.shells[0].volume == Approx(8.0).epsilon(1e-12));
  CHECK(c.shells[1].volume == Approx(-1.0).epsilon(1e-12));
  CHECK(c.shells[1].triangles.front() == 12);
  // An island met before its cavity is named as one, with the cavity (its innermost container).
  const Mesh island_first = combine({{box(4.0)}, {box(1.0)}, {box(2.0), true}});
  CHECK(refusal(island_first) == "(valid)");
  CHECK_THAT(classify_shells(island_first).reason,
             Contains("shell 1 (12 triangles from triangle 12) is an island in the cavity shell 2 (12 triangles from triangle 24)"));
}

TEST_CASE("solids: nested shells of one orientation are refused", "[hostile][solids]") {
  const std::vector<std::pair<std::string, Mesh>> meshes = {
      {"box in a box", combine({{box(2.0)}, {box(1.0)}})},
      {"inner shell first", combine({{box(1.0)}, {box(2.0)}})},
      {"sphere in a box, off centre", combine({{box(3.0)}, {sphere(0.5, Vec3(0.7, -0.6, 0.2))}})},
      {"three nested boxes", combine({{box(3.0)}, {box(2.0)}, {box(1.0)}})},
      {"cavity holding an inward shell", combine({{box(4.0)}, {box(2.0), true}, {box(1.0), true}})},
  };
  for (const auto& [name, mesh] : meshes) {
    INFO(name);
    CHECK(classify_shells(mesh).verdict == SolidVerdict::invalid);
    const std::string error = refusal(mesh);
    CHECK_THAT(error, Contains("nested shells of one orientation"));
    CHECK(error.find('\n') == std::string::npos);
  }
  // The innermost container is named: in three nested boxes, box 1 m lies in box 2 m, not in 3 m.
  const ShellClassification c = classify_shells(combine({{box(3.0)}, {box(2.0)}, {box(1.0)}}));
  CHECK(c.shells[1].container == 0);
  CHECK(c.shells[2].container == 1);
  CHECK_THAT(refusal(combine({{box(1.0)}, {box(2.0)}})), Contains("shell 0 (12 triangles from triangle 0) lies inside shell 1"));
}

TEST_CASE("solids: shells that cross are refused, naming both and a pair of triangles", "[hostile][solids]") {
  const std::vector<std::pair<std::string, Mesh>> meshes = {
      {"two overlapping cubes", combine({{box(1.0)}, {box(1.0, Vec3(0.5, 0.25, 0.125))}})},
      {"a sphere through a box face", combine({{box(2.0)}, {sphere(0.5, Vec3(1.0, 0.1, 0.2))}})},
      {"an inward box crossing an outward one", combine({{box(2.0)}, {box(1.0, Vec3(0.9, 0, 0)), true}})},
      {"a copy of the box moved by a millimetre", combine({{box(1.0)}, {box(1.0, Vec3(1e-3, 2e-3, 3e-3))}})},
      {"boxes touching over a face", combine({{box(1.0)}, {box(1.0, Vec3(1.0, 0.3, 0.2))}})},
  };
  for (const auto& [name, mesh] : meshes) {
    INFO(name);
    CHECK(classify_shells(mesh).verdict == SolidVerdict::invalid);
    const std::string error = refusal(mesh);
    CHECK_THAT(error, Contains("shells cross: shell 0 (") && Contains("and shell 1 (") && Contains("intersect (triangles"));
    CHECK(error.find('\n') == std::string::npos);
  }
}

TEST_CASE("solids: shells of mixed orientation that make no cavity are refused", "[hostile][solids]") {
  const std::vector<std::pair<std::string, Mesh>> meshes = {
      {"outward box beside an inward box", combine({{box(1.0)}, {box(1.0, Vec3(3, 0, 0)), true}})},
      {"inward sphere beside an outward box", combine({{sphere(1.0, Vec3(0, 4, 0)), true}, {box(1.0)}})},
      {"hollow box beside an inward box", combine({{box(2.0)}, {box(1.0), true}, {box(1.0, Vec3(5, 0, 0)), true}})},
      {"outward box inside an inward box inside nothing beside an outward box",
       combine({{box(3.0), true}, {box(1.0)}, {box(1.0, Vec3(6, 0, 0))}})},
  };
  for (const auto& [name, mesh] : meshes) {
    INFO(name);
    const ShellClassification c = classify_shells(mesh);
    CHECK(c.verdict == SolidVerdict::invalid);
    CHECK_FALSE(c.inverted);
    const std::string error = refusal(mesh);
    CHECK_THAT(error, Contains("shells of mixed orientation") && Contains("faces inward and lies inside no other shell"));
    CHECK(error.find('\n') == std::string::npos);
  }
}

TEST_CASE("solids: disjoint outward shells are one solid whose volume is their sum", "[hostile][solids]") {
  struct Accepted {
    std::string name;
    Mesh mesh;
    double volume;  // m^3, exact for boxes
    int shells;
  };
  std::vector<Part> row;
  double row_volume = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double size = 0.5 + 0.1 * i;
    row.push_back({box(size, Vec3(2.0 * i, (i % 3) * 0.25, 0))});
    row_volume += size * size * size;
  }
  const Mesh ball = sphere(1.0, Vec3(5, 0, 0));
  const double ball_volume = signed_volume(ball);
  // Two linked rings: their boxes overlap and each passes through the other's hole, yet they
  // neither cross nor hold one another. The second is the first turned a quarter about x (a
  // rotation keeps the orientation) and moved along x by the major radius.
  const Mesh ring = make_torus(1.0, 0.25, 32, 12);
  Mesh linked = ring;
  for (Vec3& p : linked.vertices) p = Vec3(p.x() + 1.0, -p.z(), p.y());
  const double ring_volume = signed_volume(ring);
  const std::vector<Accepted> cases = {
      {"two boxes", combine({{box(1.0)}, {box(2.0, Vec3(3, 0, 0))}}), 1.0 + 8.0, 2},
      {"a box and a sphere", combine({{box(2.0)}, {ball}}), 8.0 + ball_volume, 2},
      {"ten boxes in a row", combine(row), row_volume, 10},
      {"two linked rings", combine({{ring}, {linked}}), 2.0 * ring_volume, 2},
      {"two boxes apart on the diagonal", combine({{box(1.0)}, {box(1.0, Vec3(1.5, 1.5, 1.5))}}), 2.0, 2},
  };
  for (const Accepted& a : cases) {
    INFO(a.name);
    const ShellClassification c = classify_shells(a.mesh);
    CHECK(c.verdict == SolidVerdict::solid);
    for (const Shell& s : c.shells) CHECK(s.container == -1);
    Result<Solid> solid = make_solid(a.mesh, a.name);
    REQUIRE(solid.ok());
    CHECK_FALSE(solid->report.flipped);
    CHECK(solid->report.shells == a.shells);
    CHECK(solid->mass.volume == Approx(a.volume).epsilon(1e-12));
  }
}

TEST_CASE("solids: a solid read inside out is flipped and accepted", "[hostile][solids]") {
  const std::vector<std::pair<Mesh, double>> meshes = {
      {combine({{box(1.0), true}}), 1.0},
      {combine({{box(2.0, Vec3(1, 2, 3)), true}}), 8.0},
      {combine({{box(1.0), true}, {box(1.0, Vec3(3, 0, 0)), true}}), 2.0},
  };
  for (const auto& [mesh, volume] : meshes) {
    CHECK(classify_shells(mesh).inverted);
    Result<Solid> solid = make_solid(mesh, "inward");
    REQUIRE(solid.ok());
    CHECK(solid->report.flipped);
    CHECK(solid->mass.volume == Approx(volume).epsilon(1e-12));
  }
  // A hollow solid inside out (outer shell inward, cavity outward) is still a solid with a cavity.
  const Mesh inside_out = combine({{box(2.0), true}, {box(1.0)}});
  const ShellClassification c = classify_shells(inside_out);
  CHECK(c.inverted);
  CHECK(c.verdict == SolidVerdict::with_cavities);
  CHECK(refusal(inside_out) == "(valid)");  // turned outward by validate_solid
}

TEST_CASE("solids: fragments are judged by the rule every solid passes", "[hostile][solids][fracture-metrics]") {
  const Mesh input = box(4.0);
  const MassProperties input_mass = mass_properties(input);
  const auto fragment_of = [](const Mesh& mesh) { return Fragment{mesh, mass_properties(mesh)}; };
  struct Bad {
    std::string name;
    Mesh mesh;
    std::string problem;
  };
  const std::vector<Bad> bad = {
      {"nested outward boxes", combine({{box(4.0)}, {box(1.0)}}), "nested shells of one orientation"},
      {"crossing boxes", combine({{box(4.0)}, {box(1.0, Vec3(2, 0, 0))}}), "shells cross"},
      {"mixed orientation", combine({{box(2.0, Vec3(-1, 0, 0))}, {box(1.0, Vec3(1, 0, 0)), true}}),
       "shells of mixed orientation"},
      {"inward box", combine({{box(4.0), true}}), "is not positive"},
  };
  for (const Bad& b : bad) {
    INFO(b.name);
    const std::vector<Fragment> fragments = {fragment_of(b.mesh)};
    const FractureMetrics m = fracture_metrics(input, input_mass, fragments, 1);
    CHECK_FALSE(m.all_closed);
    CHECK_THAT(m.fragment_problem, Catch::StartsWith("fragment 0: ") && Contains(b.problem));
    const std::vector<std::string> failed = failed_fracture_checks(m);
    REQUIRE_FALSE(failed.empty());
    CHECK_THAT(failed.front(), Catch::StartsWith("all_closed: fragment 0: ") && Contains(b.problem));
  }
  // A fragment may hold a cavity (it is a valid solid); the input's cavity is then covered exactly.
  const Mesh hollow = combine({{box(4.0)}, {box(1.0), true}});
  const std::vector<Fragment> fragments = {fragment_of(hollow)};
  const FractureMetrics m = fracture_metrics(hollow, mass_properties(hollow), fragments, 1);
  CHECK(m.all_closed);
  CHECK(m.fragment_problem.empty());
  CHECK(failed_fracture_checks(m).empty());
}

TEST_CASE("results: a fracture whose figures break a threshold fails that check, and only that one",
          "[hostile][solids][fracture-metrics]") {
  FractureMetrics good;
  good.fragment_count = 5;
  good.requested = 5;
  good.volume_error = 2e-16;
  good.partition_samples = 2000;
  CHECK(failed_fracture_checks(good).empty());

  const auto only = [](const FractureMetrics& m, const std::string& check) {
    const std::vector<std::string> failed = failed_fracture_checks(m);
    REQUIRE(failed.size() == 1);
    CHECK_THAT(failed.front(), Catch::StartsWith(check));
  };
  FractureMetrics m = good;
  m.volume_error = 7.9;
  only(m, "volume_error 7.9 > 1e-06");
  m.volume_error = 2e-6;
  only(m, "volume_error 2e-06 > 1e-06");
  m.volume_error = std::numeric_limits<double>::quiet_NaN();
  only(m, "volume_error nan");
  m = good;
  m.partition_error = 1.0;
  only(m, "partition_error 1 > 0.01");
  m.partition_error = 0.0105;
  only(m, "partition_error 0.0105 > 0.01");
  m = good;
  m.all_closed = false;
  m.fragment_problem = "fragment 3: volume -0.49 is not positive";
  only(m, "all_closed: fragment 3: volume -0.49 is not positive");
  m = good;
  m.fragment_count = 0;
  only(m, "fragments: no fragment");

  // A grid cell is held to the same thresholds, pre-fracture and runtime apart; a cell that did not
  // run reports why elsewhere.
  GridCell cell;
  CHECK(failed_cell_checks(cell).empty());
  cell.accuracy.runtime_all_closed = false;
  cell.accuracy.prefracture_volume_error = 0.3;
  const std::vector<std::string> failed = failed_cell_checks(cell);
  REQUIRE(failed.size() == 2);
  CHECK(failed[0] == "pre-fracture: volume_error 0.3 > 1e-06");
  CHECK(failed[1] == "runtime: all_closed: a fragment is not a valid solid");
  GridResult grid;
  grid.cells = {cell};
  CHECK_FALSE(grid.passed());
  cell.failed = "timeout after 2 s";
  CHECK(failed_cell_checks(cell).empty());
}

TEST_CASE("solids: with --no-repair every command refuses an invalid solid with exit 2 and one line", "[hostile][solids][cli]") {
  const auto dir = scratch("cli");
  struct File {
    std::string name;
    Mesh mesh;
    std::string reason;
  };
  const std::vector<File> files = {
      {"nested.off", combine({{box(2.0)}, {box(1.0)}}), "nested shells of one orientation"},
      {"crossing.obj", combine({{box(1.0)}, {box(1.0, Vec3(0.5, 0.25, 0.125))}}), "shells cross"},
      {"mixed.off", combine({{box(1.0)}, {box(1.0, Vec3(3, 0, 0)), true}}), "shells of mixed orientation"},
  };
  nlohmann::json base;
  std::ifstream(std::filesystem::path(SHATTER_SOURCE_DIR) / "cases" / "wall.json") >> base;
  for (const File& f : files) {
    const std::filesystem::path path = dir / f.name;
    write_mesh(f.mesh, path);
    nlohmann::json c = base;
    c["name"] = "hostile-" + path.stem().string();
    c["mesh"] = {{"file", path.string()}};
    const std::filesystem::path case_path = dir / (path.stem().string() + ".json");
    std::ofstream(case_path) << c.dump(1);
    const std::filesystem::path out = dir / "out";
    // The acceptance rule's refusal, as every command gives it when repair is off (by default the
    // same files are repaired: the next test case).
    const std::vector<std::vector<std::string>> commands = {
        {"fracture", "--mesh", path.string(), "--algo", "plane-slice", "--fragments", "4", "--no-repair"},
        {"fracture", "--mesh", path.string(), "--algo", "cgal-clip", "--fragments", "4", "--out", out.string(), "--no-repair"},
        {"table", "--mesh", path.string(), "--fragments", "4", "--repetitions", "1", "--no-repair"},
        {"stress", "--case", case_path.string(), "--no-repair"},
        {"grid", "--case", case_path.string(), "--repetitions", "1", "--frames", "2", "--json", (dir / "g.json").string(), "--no-repair"},
        {"accuracy", "--case", case_path.string(), "--family", "fracture", "--repetitions", "1", "--no-repair"},
    };
    for (const std::vector<std::string>& args : commands) {
      INFO(f.name << ": " << args[0] << " " << args[1] << " " << args[2]);
      const test::CliRun run = test::run_cli_argv(args);
      CHECK(run.exit_code == 2);
      CHECK(test::line_count(run.err) == 1);
      CHECK_THAT(run.err, Catch::StartsWith("shatterbench: error: ") && Contains(f.name) && Contains(f.reason));
      CHECK(run.out.empty());
      CHECK_FALSE(std::filesystem::exists(out));
      CHECK_FALSE(std::filesystem::exists(dir / "g.json"));
    }
  }
}

TEST_CASE("solids: the CLI fractures disjoint shells and a flipped solid, and checks its result", "[hostile][solids][cli]") {
  const auto dir = scratch("cli_ok");
  const std::string two = write_mesh(combine({{box(1.0)}, {box(2.0, Vec3(3, 0, 0))}}), dir / "two.off");
  const std::string inward = write_mesh(combine({{box(2.0), true}}), dir / "inward.off");
  for (const std::string algo : {"plane-slice", "voronoi", "fem-lite", "cgal-clip"}) {
    INFO(algo);
    for (const auto& [path, volume, flipped] : {std::tuple{two, 9.0, false}, std::tuple{inward, 8.0, true}}) {
      INFO(path);
      const test::CliRun run = test::run_cli_argv({"fracture", "--mesh", path, "--algo", algo, "--fragments", "6"});
      REQUIRE(run.exit_code == 0);
      CHECK(run.err.empty());
      const nlohmann::json out = nlohmann::json::parse(run.out);
      CHECK(out["input"]["volume"].get<double>() == Approx(volume).epsilon(1e-12));
      CHECK(out["input"]["flipped"].get<bool>() == flipped);
      CHECK(out["metrics"]["all_closed"].get<bool>());
      CHECK(out["metrics"]["volume_error"].get<double>() <= 1e-6);
    }
  }
  const test::CliRun table = test::run_cli_argv({"table", "--mesh", two, "--mesh", inward, "--fragments", "3", "9", "--repetitions", "1"});
  CHECK(table.exit_code == 0);
  CHECK(table.err.empty());
  CHECK(table.out.find("| NO |") == std::string::npos);
}

TEST_CASE("solids: by default every command repairs the invalid arrangements into the solid they describe",
          "[hostile][solids][cli][repair]") {
  const auto dir = scratch("cli_repaired");
  struct File {
    std::string name;
    Mesh mesh;
    double volume;  // analytic, of the solid the shells describe
    int cavities;
  };
  // Nested outward boxes: the inner one turned into a cavity, 8 - 1. Crossing unit boxes: their union,
  // 2 - 0.5 x 0.75 x 0.875. A box beside an inward box: both outward, 1 + 1. A hollow sphere is a solid
  // as it is: outer minus inner polyhedron.
  const Mesh hollow = combine({{sphere(1.0)}, {sphere(0.5), true}});
  const std::vector<File> files = {
      {"nested.off", combine({{box(2.0)}, {box(1.0)}}), 7.0, 1},
      {"crossing.obj", combine({{box(1.0)}, {box(1.0, Vec3(0.5, 0.25, 0.125))}}), 2.0 - 0.5 * 0.75 * 0.875, 0},
      {"mixed.off", combine({{box(1.0)}, {box(1.0, Vec3(3, 0, 0)), true}}), 2.0, 0},
      {"hollow.off", hollow, mass_properties(hollow).volume, 1},
  };
  for (const File& f : files) {
    const std::filesystem::path path = dir / f.name;
    write_mesh(f.mesh, path);
    for (const std::string algo : {"plane-slice", "voronoi", "fem-lite", "cgal-clip"}) {
      INFO(f.name << " with " << algo);
      const test::CliRun run = test::run_cli_argv({"fracture", "--mesh", path.string(), "--algo", algo, "--fragments", "6"});
      INFO(run.err);
      REQUIRE(run.exit_code == 0);
      const nlohmann::json out = nlohmann::json::parse(run.out);
      CHECK(out["input"]["volume"].get<double>() == Approx(f.volume).epsilon(1e-9));
      CHECK(out["input"]["repairs"]["cavities"].get<int>() == f.cavities);
      CHECK(out["input"]["repairs"]["repaired"].get<bool>() == (f.name != "hollow.off"));
      CHECK(out["metrics"]["all_closed"].get<bool>());
      CHECK(out["metrics"]["volume_error"].get<double>() <= 1e-9);
      CHECK(out["metrics"]["partition_error"].get<double>() == 0.0);
    }
  }
}
