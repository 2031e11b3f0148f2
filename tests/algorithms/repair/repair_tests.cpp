#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/core/self_intersection.h"
#include "algorithms/core/shell_classification.h"
#include "algorithms/repair/hausdorff_distance.h"
#include "algorithms/repair/repair_solid.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// The acceptance rule with cavities allowed and the self-intersection test: validate_solid on a
/// copy, accepting a refusal that is only the cavity verdict of classify_shells.
void require_solid(const Mesh& mesh) {
  REQUIRE(mesh.tags.size() == mesh.triangles.size());
  REQUIRE(all_finite(mesh));
  REQUIRE(is_closed_and_oriented(mesh));
  Mesh copy = mesh;
  const Result<ValidationReport> valid = validate_solid(copy, "repaired");
  if (valid) {
    REQUIRE_FALSE(valid->flipped);
  } else {
    INFO(valid.error().message);
    const ShellClassification shells = classify_shells(copy);
    REQUIRE(shells.verdict == SolidVerdict::with_cavities);
    REQUIRE_FALSE(shells.inverted);
  }
  REQUIRE_FALSE(find_self_intersection(mesh).has_value());
}

/// `mesh` without the triangles whose corners all satisfy `drop`.
template <class Predicate>
Mesh without(const Mesh& mesh, Predicate drop) {
  Mesh out;
  out.vertices = mesh.vertices;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (drop(mesh.vertices[t[0]]) && drop(mesh.vertices[t[1]]) && drop(mesh.vertices[t[2]])) continue;
    out.add_triangle(t[0], t[1], t[2], mesh.tags[f]);
  }
  return out;
}

/// `b` appended to `a` as one soup.
Mesh soup_of(Mesh a, const Mesh& b) {
  append_mesh(a, b);
  return a;
}

RepairedSolid repaired(const Mesh& soup) {
  Result<RepairedSolid> result = repair_solid(soup, "test");
  INFO((result ? std::string() : result.error().message));
  REQUIRE(result.ok());
  return std::move(result).value();
}

}  // namespace

TEST_CASE("repair: a cube with one face removed is filled back to the cube", "[repair]") {
  const Mesh cube = make_box(Vec3::Ones());  // [-0.5, 0.5]^3
  const Mesh open = without(cube, [](const Vec3& p) { return p.z() == 0.5; });
  REQUIRE(open.triangles.size() + 2 == cube.triangles.size());

  const RepairedSolid solid = repaired(open);
  require_solid(solid.mesh);
  CHECK(signed_volume(solid.mesh) == Approx(1.0).margin(1e-12));
  CHECK(solid.report.holes_filled == 1);
  CHECK(solid.report.hole_area == Approx(1.0).margin(1e-12));
  CHECK(tagged_area(solid.mesh, FaceTag::repair) == Approx(1.0).margin(1e-12));
  CHECK(tagged_area(solid.mesh, FaceTag::surface) == Approx(5.0).margin(1e-12));
  CHECK(solid.report.sheets_removed == 0);
  CHECK(solid.report.repaired);
  CHECK(solid.report.self_intersection_fix.empty());
  // The filling lies in the removed face: at most half its side from the side faces' edges.
  CHECK(solid.report.hausdorff_distance > 0.0);
  CHECK(solid.report.hausdorff_distance <= 0.5 + 1e-12);
  CHECK(solid.report.time_ms > 0.0);
}

TEST_CASE("repair: two overlapping unit cubes in one soup become their union", "[repair]") {
  const Mesh soup = soup_of(make_box(Vec3::Ones()), make_box(Vec3::Ones(), Vec3(0.5, 0.0, 0.0)));
  const RepairedSolid solid = repaired(soup);
  require_solid(solid.mesh);
  CHECK(signed_volume(solid.mesh) == Approx(1.5).margin(1e-12));
  CHECK(surface_area(solid.mesh) == Approx(8.0).margin(1e-12));  // 1.5 x 1 x 1 box
  CHECK(solid.report.self_intersections > 0);
  CHECK(solid.report.self_intersection_fix == "autorefine");
  CHECK(solid.report.shells == 1);
  CHECK(solid.report.cavities == 0);
  // Pieces of input faces keep the input's tag: nothing was added.
  CHECK(tagged_area(solid.mesh, FaceTag::repair) == 0.0);
  // The removed inner faces lie at most 0.5 from the union's surface (the centre of x = 0 or x = 0.5).
  CHECK(solid.report.hausdorff_distance <= 0.5 + 1e-12);
  CHECK(solid.report.hausdorff_distance == Approx(0.5).margin(0.02));
}

TEST_CASE("repair: shells of mixed orientation are oriented to bound a volume with a cavity", "[repair]") {
  // Outer box 2^3 wholly inward; inner box 1^3 with every other triangle reversed.
  const Mesh outer = reversed_mesh(make_box(Vec3::Constant(2.0)));
  Mesh inner = make_box(Vec3::Ones());
  for (std::size_t f = 0; f < inner.triangles.size(); f += 2) std::swap(inner.triangles[f][1], inner.triangles[f][2]);
  const RepairedSolid solid = repaired(soup_of(outer, inner));
  require_solid(solid.mesh);
  CHECK(signed_volume(solid.mesh) == Approx(8.0 - 1.0).margin(1e-12));
  CHECK(solid.report.shells == 2);
  CHECK(solid.report.cavities == 1);
  CHECK(solid.report.faces_reoriented > 0);
  CHECK(solid.report.hausdorff_distance <= 1e-12);
}

TEST_CASE("repair: an open flat sheet is refused with a reason", "[repair]") {
  Mesh quad;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) quad.add_vertex(p);
  quad.add_triangle(0, 1, 2, FaceTag::surface);
  quad.add_triangle(0, 2, 3, FaceTag::surface);
  const Result<RepairedSolid> result = repair_solid(quad, "quad.off");
  REQUIRE_FALSE(result.ok());
  CHECK_THAT(result.error().message, StartsWith("quad.off: ") && Contains("open sheet encloses no volume"));
  CHECK(result.error().message.find('\n') == std::string::npos);
}

TEST_CASE("repair: a shallow open patch is a sheet, a deep bowl a solid with a hole", "[repair]") {
  // A box missing its top face: depth / width = height / side. 1/50 is a sheet, 1/5 a tray.
  const Mesh shallow = without(make_box(Vec3(1.0, 1.0, 0.02)), [](const Vec3& p) { return p.z() == 0.01; });
  const Result<RepairedSolid> sheet = repair_solid(shallow, "shallow");
  REQUIRE_FALSE(sheet.ok());
  CHECK_THAT(sheet.error().message, Contains("open sheet"));

  const Mesh deep = without(make_box(Vec3(1.0, 1.0, 0.2)), [](const Vec3& p) { return p.z() == 0.1; });
  const RepairedSolid tray = repaired(deep);
  require_solid(tray.mesh);
  CHECK(signed_volume(tray.mesh) == Approx(0.2).margin(1e-12));

  // Beside a solid, the sheet is dropped and counted.
  const Mesh both = soup_of(make_box(Vec3::Ones()), without(make_box(Vec3(1.0, 1.0, 0.02), Vec3(3, 0, 0)),
                                                            [](const Vec3& p) { return p.z() == 0.01; }));
  const RepairedSolid solid = repaired(both);
  require_solid(solid.mesh);
  CHECK(solid.report.sheets_removed == 1);
  CHECK(signed_volume(solid.mesh) == Approx(1.0).margin(1e-12));
}

TEST_CASE("repair: a box whose faces each have their own vertices is welded", "[repair]") {
  const Mesh box = make_box(Vec3(1.0, 2.0, 3.0));
  Mesh seams = triangle_soup(box);
  // Tags survive: mark the first two triangles as cut faces.
  seams.tags[0] = seams.tags[1] = FaceTag::cut;
  const double cut_area = tagged_area(seams, FaceTag::cut);
  const RepairedSolid solid = repaired(seams);
  require_solid(solid.mesh);
  CHECK(solid.report.vertices_merged == static_cast<int>(seams.vertices.size()) - 8);
  CHECK(solid.mesh.vertices.size() == 8);
  CHECK(signed_volume(solid.mesh) == Approx(6.0).margin(1e-12));
  CHECK(tagged_area(solid.mesh, FaceTag::cut) == Approx(cut_area).margin(1e-12));
  CHECK(solid.report.holes_filled == 0);
  CHECK(solid.report.hausdorff_distance <= 1e-12);
}

TEST_CASE("repair: a sphere with random face orientations is oriented outward", "[repair]") {
  const Mesh sphere = make_sphere(1.0, 24, 12);
  Mesh scrambled = sphere;
  SplitMix64 random(19);
  int flipped = 0;
  for (Triangle& t : scrambled.triangles)
    if (random.uniform() < 0.5) {
      std::swap(t[1], t[2]);
      ++flipped;
    }
  const RepairedSolid solid = repaired(scrambled);
  require_solid(solid.mesh);
  CHECK(solid.mesh.triangles.size() == sphere.triangles.size());
  CHECK(signed_volume(solid.mesh) == Approx(signed_volume(sphere)).epsilon(1e-12));
  CHECK(solid.report.faces_reoriented == flipped);
  // Only reoriented: the surfaces coincide.
  CHECK(solid.report.hausdorff_distance <= 1e-12 * 2.0);
  CHECK(solid.report.holes_filled == 0);
  CHECK(solid.report.self_intersections == 0);
}

TEST_CASE("repair: an inside-out sphere is turned outward with Hausdorff distance 0", "[repair]") {
  const Mesh sphere = make_sphere(2.0);
  const RepairedSolid solid = repaired(reversed_mesh(sphere));
  require_solid(solid.mesh);
  CHECK(solid.report.faces_reoriented == static_cast<int>(sphere.triangles.size()));
  CHECK(signed_volume(solid.mesh) == Approx(signed_volume(sphere)).epsilon(1e-12));
  CHECK(solid.report.hausdorff_distance <= 1e-12 * 4.0);
}

TEST_CASE("repair: bad input is one error line", "[repair]") {
  CHECK_THAT(repair_solid(Mesh{}, "empty.off").error().message, StartsWith("empty.off: "));
  Mesh nan_box = make_box(Vec3::Ones());
  nan_box.vertices[0].x() = std::nan("");
  CHECK_THAT(repair_solid(nan_box, "nan.off").error().message, StartsWith("nan.off: ") && Contains("non-finite"));
}

TEST_CASE("repair: data set open cubes are filled to their bounding box, flat sheets refused", "[repair]") {
  if (!test::have_meshes()) return;
  for (const std::string name : {"cube-ouvert.off", "open_cube.off"}) {
    INFO(name);
    const std::filesystem::path path = test::mesh_dir() / name;
    REQUIRE(std::filesystem::exists(path));
    const Result<Mesh> mesh = read_mesh(path);
    REQUIRE(mesh.ok());
    const RepairedSolid solid = repaired(*mesh);
    require_solid(solid.mesh);
    const Aabb box = bounding_box(solid.mesh);  // of the used vertices (cube-ouvert.off has a stray one)
    const Vec3 size = box.max - box.min;
    // An axis-aligned box missing a face: the filled solid is the box of its corners.
    CHECK(signed_volume(solid.mesh) == Approx(size.prod()).epsilon(1e-12));
    CHECK(solid.report.holes_filled == 1);
  }
  for (const std::string name : {"quad.off", "triangle.off", "mesh_with_colors.off"}) {
    INFO(name);
    const std::filesystem::path path = test::mesh_dir() / name;
    REQUIRE(std::filesystem::exists(path));
    const Result<Mesh> mesh = read_mesh(path);
    REQUIRE(mesh.ok());
    const Result<RepairedSolid> result = repair_solid(*mesh, name);
    REQUIRE_FALSE(result.ok());
    CHECK_THAT(result.error().message, StartsWith(name + ": ") && Contains("open sheet"));
  }
}

TEST_CASE("repair: the Hausdorff estimate is the same on every call and bounded by the true distance", "[repair]") {
  // Two overlapping unit cubes against their union, the 1.5 x 1 x 1 box: the inner faces' centres lie
  // 0.5 from the box, nothing lies farther, so the true distance is 0.5 and samples give at most that.
  Mesh soup = make_box(Vec3::Ones());
  append_mesh(soup, make_box(Vec3::Ones(), Vec3(0.5, 0.0, 0.0)));
  const Mesh box = make_box(Vec3(1.5, 1.0, 1.0), Vec3(0.25, 0.0, 0.0));
  const double first = repair::hausdorff_distance(soup, box);
  CHECK(repair::hausdorff_distance(soup, box) == first);
  CHECK(repair::hausdorff_distance(box, soup) == first);
  CHECK(first <= 0.5 + 1e-12);
  CHECK(first >= 0.45);
}
