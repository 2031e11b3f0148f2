// The mesh repair under its budget (harness/cases/isolated_repair.h): a mesh whose repair would run
// for minutes, exhaust memory or crash inside CGAL is refused with one line naming the budget, and a
// repair within it gives what the repair in the process gives.

#include "algorithms/core/mesh_io.h"
#include "algorithms/core/primitives.h"
#include "harness/cases/isolated_repair.h"
#include "tests/hostile/hostile_support.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace shatter;
using namespace shatter::test;
namespace fs = std::filesystem;

namespace {

/// A cap of `corners` boundary vertices fanned from a raised centre, its rim zigzagging up and down:
/// one hole of `corners` edges that no plane holds, which the hole filling closes in a time that grows
/// steeply with its length (about 90 s at 20,000 corners on a 2-core machine).
Mesh zigzag_cap(int corners) {
  Mesh m;
  m.add_vertex(Vec3(0.0, 0.0, 0.5));
  for (int i = 0; i < corners; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / corners;
    m.add_vertex(Vec3(std::cos(a), std::sin(a), 0.2 * (i % 2)));
  }
  for (int i = 0; i < corners; ++i) m.add_triangle(0, 1 + i, 1 + (i + 1) % corners, FaceTag::surface);
  return m;
}

}  // namespace

TEST_CASE("repair budget: a repair within the budget is the repair in the process", "[hostile][repair]") {
  Mesh open = make_box(Vec3(1, 2, 3), Vec3::Zero());
  open.triangles.pop_back();  // a hole of three edges
  open.tags.pop_back();
  const Result<RepairedSolid> here = repair_solid(open, "open box");
  const Result<RepairedSolid> child = repair_solid_isolated(open, "open box");
  REQUIRE(here.ok());
  INFO((child.ok() ? std::string() : child.error().message));
  REQUIRE(child.ok());
  CHECK(child->mesh.vertices == here->mesh.vertices);
  CHECK(child->mesh.triangles == here->mesh.triangles);
  CHECK(child->mesh.tags == here->mesh.tags);
  CHECK(child->report.holes_filled == here->report.holes_filled);
  CHECK(child->report.hole_area == here->report.hole_area);
  CHECK(child->report.self_intersection_fix == here->report.self_intersection_fix);
}

TEST_CASE("repair budget: a repair past its time or memory is refused, naming the budget", "[hostile][repair]") {
  RepairBudget tight;
  tight.time_s = 3.0;
  const Result<RepairedSolid> slow = repair_solid_isolated(zigzag_cap(20000), "cap.off", tight);
  REQUIRE_FALSE(slow.ok());
  CHECK_THAT(slow.error().message, Catch::StartsWith("cap.off: "));
  CHECK_THAT(slow.error().message, Catch::Contains("budget"));
  CHECK(slow.error().message.find('\n') == std::string::npos);
}

TEST_CASE("repair budget: degenerate meshes end in one line from the command line", "[hostile][repair][cli]") {
  const fs::path dir = hostile_scratch("repair_budget");
  // 100,000 copies of one face.
  Mesh copies;
  copies.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  for (int i = 0; i < 100000; ++i) copies.add_triangle(0, 1, 2, FaceTag::surface);
  REQUIRE(write_off(copies, dir / "copies.off").ok());
  const CliRun run = run_cli_argv({"fracture", "--mesh", (dir / "copies.off").string(), "--algo", "plane-slice",
                                   "--fragments", "5"});
  CHECK(run.exit_code == 2);
  CHECK(line_count(run.err) == 1);
  CHECK_THAT(run.err, Catch::Contains("copies.off"));
}
