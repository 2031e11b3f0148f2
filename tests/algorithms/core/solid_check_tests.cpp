// The acceptance rule (solid_check.h): the one definition of a self-intersection on pairs of triangles
// whose answer is known by construction, check_solid on one mesh of each failure class (one error
// line each), and the normalisation validate_solid does before applying it (pinched edges split).

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/self_intersection.h"
#include "algorithms/core/solid_check.h"

#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

using Corners = std::array<Vec3, 3>;

Mesh mesh_of(std::vector<Vec3> vertices, const std::vector<Triangle>& triangles) {
  Mesh mesh;
  mesh.vertices = std::move(vertices);
  for (const Triangle& t : triangles) mesh.add_triangle(t[0], t[1], t[2], FaceTag::surface);
  return mesh;
}

/// Both orders of the pair, and their corners rotated, give the same answer.
bool meet(const Corners& t, const Corners& u) {
  const bool a = triangles_intersect(t, u);
  CHECK(triangles_intersect(u, t) == a);
  CHECK(triangles_intersect(Corners{t[1], t[2], t[0]}, Corners{u[2], u[0], u[1]}) == a);
  return a;
}

/// Two meshes as one (indices of `b` shifted).
Mesh combined(Mesh a, const Mesh& b) {
  append_mesh(a, b);
  return a;
}

/// The error line of check_solid, or "(accepted)".
std::string verdict(const Mesh& mesh) {
  const Status s = check_solid(mesh, "solid", nullptr);
  return s ? std::string("(accepted)") : s.error().message;
}

/// Corner tetrahedron (0, e_x, e_y, e_z) and its copy rotated by pi about x, sharing the edge (0, 1).
Mesh two_tetrahedra_on_one_edge() {
  return mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}},
                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}});
}

}  // namespace

TEST_CASE("acceptance: what counts as a self-intersection", "[acceptance][self-intersection]") {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  // A corner of one triangle on the other's interior, not a corner of it: they touch there.
  CHECK(meet({o, x, y}, {Vec3(0.25, 0.25, 0), Vec3(0.25, 0.25, 1), Vec3(0.5, -0.5, 1)}));
  // A corner on the other's edge (not a corner of it) touches too.
  CHECK(meet({o, x, y}, {Vec3(0.5, 0, 0), Vec3(0.5, -1, 1), Vec3(0.5, -1, -1)}));
  // Sharing a corner by position only (two vertices, one place), meeting nowhere else: no intersection.
  CHECK_FALSE(meet({o, x, y}, {Vec3(0, 0, 0), Vec3(-1, 0, 1), Vec3(0, -1, 1)}));
  // Sharing an edge (folded or flat): no intersection.
  CHECK_FALSE(meet({o, x, y}, {x, o, z}));
  CHECK_FALSE(meet({o, x, y}, {x, o, Vec3(0.3, -1, 0)}));
  // Coplanar and overlapping: they intersect.
  CHECK(meet({o, x, y}, {Vec3(0.1, 0.1, 0), Vec3(2, 0.1, 0), Vec3(0.1, 2, 0)}));
  // Coplanar, sharing an edge, on opposite sides of it (not overlapping): no intersection.
  CHECK_FALSE(meet({o, x, y}, {x, o, Vec3(0.5, -1, 0)}));
  // Coplanar, sharing an edge, folded onto each other (overlapping): they intersect.
  CHECK(meet({o, x, y}, {x, o, Vec3(0.5, 0.2, 0)}));

  // In a mesh: shared by position only (vertices duplicated) is no intersection either.
  Mesh apart = mesh_of({o, x, y, z, o, Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1)},
                       {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 5, 6}, {4, 7, 5}, {4, 6, 7}, {5, 7, 6}});
  CHECK_FALSE(find_self_intersection(apart).has_value());
  CHECK(verdict(apart) == "(accepted)");
}

TEST_CASE("acceptance: one error line for each failure class", "[acceptance]") {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  REQUIRE(verdict(cube) == "(accepted)");
  SECTION("empty") { CHECK(verdict(Mesh{}) == "solid: empty mesh (no triangles)"); }
  SECTION("not finite, out of range") {
    Mesh m = cube;
    m.vertices[2].x() = std::numeric_limits<double>::quiet_NaN();
    CHECK_THAT(verdict(m), StartsWith("solid: vertex 2 ") && Contains("not finite"));
    m.vertices[2].x() = 3e9;
    CHECK_THAT(verdict(m), Contains("outside the representable range"));
  }
  SECTION("repeated index, zero area") {
    Mesh m = cube;
    m.triangles[3][1] = m.triangles[3][0];
    CHECK(verdict(m) == "solid: triangle 3 is degenerate (repeated vertex)");
    Mesh flat = mesh_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}});
    CHECK(verdict(flat) == "solid: triangle 0 has zero area (collinear corners)");
  }
  SECTION("open, misoriented, non-manifold edge") {
    Mesh open = cube;
    open.triangles.pop_back();
    open.tags.pop_back();
    CHECK_THAT(verdict(open), StartsWith("solid: not closed: edge (") && Contains("is used by 1 triangle"));
    Mesh flipped_face = cube;
    std::swap(flipped_face.triangles[0][1], flipped_face.triangles[0][2]);
    CHECK_THAT(verdict(flipped_face), StartsWith("solid: inconsistent orientation at edge ("));
    CHECK(verdict(two_tetrahedra_on_one_edge()) == "solid: not 2-manifold: edge (0, 1) is used by 4 triangles");
  }
  SECTION("inward, flat, crossing and nested shells") {
    CHECK_THAT(verdict(reversed_mesh(cube)), StartsWith("solid: faces inward"));
    CHECK_THAT(verdict(mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}})), Contains("zero volume"));
    CHECK_THAT(verdict(combined(cube, make_box(Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5)))), Contains("shells cross"));
    CHECK_THAT(verdict(combined(make_box(Vec3(2, 2, 2)), cube)), Contains("nested shells of one orientation"));
    CHECK_THAT(verdict(combined(cube, reversed_mesh(make_box(Vec3(1, 1, 1), Vec3(3, 0, 0))))),
               Contains("shells of mixed orientation"));
  }
  SECTION("a surface that intersects itself") {
    // One shell folded through itself: a box whose top corner is pushed down through the bottom.
    Mesh m = cube;
    for (Vec3& v : m.vertices)
      if (v.x() > 0 && v.y() > 0 && v.z() > 0) v = Vec3(0.5, 0.5, -1.5);
    CHECK_THAT(verdict(m), StartsWith("solid: the input mesh intersects itself (triangles "));
  }
  SECTION("a cavity is a solid") {
    CHECK(verdict(combined(make_box(Vec3(2, 2, 2)), reversed_mesh(cube))) == "(accepted)");
  }
}

TEST_CASE("acceptance: verdicts remember a mesh that passed", "[acceptance]") {
  SelfIntersectionVerdicts verdicts;
  const Mesh cube = make_box(Vec3(1, 1, 1));
  CHECK(check_solid(cube, "solid", &verdicts));
  CHECK(check_solid(cube, "solid", &verdicts));
  Mesh open = cube;
  open.triangles.pop_back();
  open.tags.pop_back();
  CHECK_FALSE(check_solid(open, "solid", &verdicts));
  CHECK_FALSE(check_solid(open, "solid", &verdicts));  // a refused mesh is never remembered
}

TEST_CASE("acceptance: validate_solid splits an edge shared by two volumes", "[acceptance][validation]") {
  Mesh m = two_tetrahedra_on_one_edge();
  const Result<ValidationReport> report = validate_solid(m, "pinched edge");
  REQUIRE(report.ok());
  CHECK(report->split_non_manifold_edges == 1);
  CHECK(report->split_pinched_vertices == 2);  // the second sheet's copies of both ends
  CHECK(report->shells == 2);
  CHECK(is_closed_and_oriented(m));
  CHECK(signed_volume(m) == Approx(1.0 / 3.0).epsilon(1e-15));
  CHECK(check_solid(m, "pinched edge", nullptr));

  // Two cubes sharing an edge, 2 triangles each way along it after the merge of their vertices.
  Mesh cubes = combined(make_box(Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5)), make_box(Vec3(1, 1, 1), Vec3(-0.5, -0.5, 0.5)));
  const Result<ValidationReport> r2 = validate_solid(cubes, "cubes");
  REQUIRE(r2.ok());
  CHECK(r2->merged_duplicate_vertices == 2);
  CHECK(signed_volume(cubes) == Approx(2.0).epsilon(1e-15));

  // Unbalanced uses (three triangles on one edge) are no solid: refused.
  Mesh three = two_tetrahedra_on_one_edge();
  three.triangles.pop_back();
  three.tags.pop_back();
  CHECK_FALSE(validate_solid(three, "three").ok());
}

TEST_CASE("acceptance: validate_solid accepts a solid with a cavity", "[acceptance][validation]") {
  Mesh hollow = combined(make_box(Vec3(2, 2, 2)), reversed_mesh(make_box(Vec3(1, 1, 1))));
  const Result<ValidationReport> report = validate_solid(hollow, "hollow");
  REQUIRE(report.ok());
  CHECK(report->shells == 2);
  CHECK(report->cavities == 1);
  CHECK_FALSE(report->flipped);
  CHECK(signed_volume(hollow) == Approx(7.0).epsilon(1e-15));
}
