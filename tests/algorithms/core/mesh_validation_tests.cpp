#include "algorithms/core/edge_classification.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "tests/support/mesh_fixtures.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

Mesh mesh_of(std::vector<Vec3> vertices, const std::vector<Triangle>& triangles) {
  Mesh mesh;
  mesh.vertices = std::move(vertices);
  for (const Triangle& t : triangles) mesh.add_triangle(t[0], t[1], t[2], FaceTag::surface);
  return mesh;
}

/// Corner tetrahedron (0, e_x, e_y, e_z) followed by its copy rotated by pi about x, sharing the
/// edge (0, 1): a closed, oriented but pinched (non-manifold) edge.
Mesh two_tetrahedra_on_one_edge() {
  return mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}},
                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}});
}

std::string error_of(Mesh mesh, const std::string& what = "test") {
  const Result<ValidationReport> report = validate_solid(mesh, what);
  return report.ok() ? std::string("(no error)") : report.error().message;
}

Vec3 naive_cross(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

}  // namespace

TEST_CASE("validation: a box is valid and left as it is", "[validation]") {
  Mesh box = make_box(Vec3(1, 2, 3));
  const Mesh original = box;
  const Result<ValidationReport> report = validate_solid(box, "box");
  REQUIRE(report.ok());
  CHECK_FALSE(report->flipped);
  CHECK(box.vertices == original.vertices);
  CHECK(box.triangles == original.triangles);
}

TEST_CASE("validation: an inward box is flipped and reported", "[validation]") {
  Mesh box = make_box(Vec3(1, 2, 3));
  for (Triangle& t : box.triangles) std::swap(t[0], t[1]);
  CHECK(is_closed_and_oriented(box));  // consistently inward is still consistent
  const Result<ValidationReport> report = validate_solid(box, "box");
  REQUIRE(report.ok());
  CHECK(report->flipped);
  CHECK(signed_volume(box) == Approx(6.0).epsilon(1e-14));
}

TEST_CASE("validation: bad meshes get messages naming the culprit", "[validation]") {
  CHECK_THAT(error_of(Mesh{}, "empty.off"), StartsWith("empty.off: ") && Contains("empty"));

  Mesh box = make_box(Vec3(1, 1, 1));
  box.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(error_of(box), Contains("vertex 3") && Contains("non-finite"));

  box = make_box(Vec3(1, 1, 1));
  box.triangles[5][1] = 8;
  CHECK_THAT(error_of(box), Contains("triangle 5") && Contains("out of range"));

  box = make_box(Vec3(1, 1, 1));
  box.triangles[2][2] = box.triangles[2][0];
  CHECK_THAT(error_of(box), Contains("triangle 2") && Contains("degenerate"));

  box = make_box(Vec3(1, 1, 1));
  box.triangles.pop_back();
  box.tags.pop_back();
  CHECK(!is_closed_and_oriented(box));
  CHECK_THAT(error_of(box), Contains("not closed: edge (") && Contains("is used by 1 triangle"));

  box = make_box(Vec3(1, 1, 1));
  std::swap(box.triangles[4][1], box.triangles[4][2]);
  CHECK(!is_closed_and_oriented(box));
  CHECK_THAT(error_of(box), Contains("inconsistent orientation at edge ("));
}

TEST_CASE("validation: a pinched edge is split into two sheets", "[validation]") {
  Mesh mesh = two_tetrahedra_on_one_edge();
  CHECK(signed_volume(mesh) == Approx(1.0 / 3.0));
  CHECK(!is_closed_and_oriented(mesh));
  CHECK(error_of(mesh) == "(no error)");
}

TEST_CASE("validation: an edge used by four triangles, three of them one way, is not 2-manifold", "[validation]") {
  Mesh mesh = two_tetrahedra_on_one_edge();
  mesh.triangles[4] = {0, 1, 4};  // now three triangles run 0 -> 1
  CHECK_THAT(error_of(mesh), Contains("not 2-manifold: edge (0, 1) is used by 4 triangles"));
}

TEST_CASE("validation: a flat closed mesh has zero volume", "[validation]") {
  Mesh pillow = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
  CHECK_THAT(error_of(pillow), Contains("zero volume"));
}

TEST_CASE("validation: duplicate and unused vertices are merged and dropped", "[validation]") {
  const Mesh box = make_box(Vec3(1, 2, 3));
  Mesh soup;  // every triangle with its own three vertices, plus two unused ones
  soup.add_vertex(Vec3(9, 9, 9));
  for (const Triangle& t : box.triangles) {
    const std::int32_t a = soup.add_vertex(box.vertices[t[0]]);
    const std::int32_t b = soup.add_vertex(box.vertices[t[1]]);
    const std::int32_t c = soup.add_vertex(box.vertices[t[2]]);
    soup.add_triangle(a, b, c, FaceTag::surface);
  }
  soup.add_vertex(Vec3(-9, 9, 9));
  CHECK(!is_closed_and_oriented(soup));
  const Result<ValidationReport> report = validate_solid(soup, "soup");
  REQUIRE(report.ok());
  CHECK(report->merged_duplicate_vertices == 36 - 8);
  CHECK(report->removed_unused_vertices == 2);
  CHECK(soup.vertices.size() == 8);
  CHECK(is_closed_and_oriented(soup));
  CHECK(signed_volume(soup) == Approx(6.0).epsilon(1e-14));
}

TEST_CASE("validation: collinearity is decided exactly", "[validation]") {
  // a, 2a, 4a are exactly collinear (scaling by 2 is exact), but the rounded cross product is not zero.
  const Vec3 a(0.1, 0.2, 0.3);
  REQUIRE(naive_cross(a, 2 * a, 4 * a) != Vec3::Zero());
  CHECK_THAT(error_of(mesh_of({a, 2 * a, 4 * a}, {{0, 1, 2}})), Contains("triangle 0 has zero area"));

  // A 2 x 2 x 2 cube whose top face has an extra vertex m a hair (2^-60) off the diagonal (4, 7):
  // the sliver (4, m, 7) has a rounded cross product of exactly zero, but a positive true area.
  const Vec3 m(std::ldexp(1.0, -60), 0.0, 1.0);
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k) corners.emplace_back(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
  REQUIRE(naive_cross(corners[4], m, corners[7]) == Vec3::Zero());
  corners.push_back(m);
  Mesh cube = mesh_of(corners, {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                                {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5},
                                {4, 5, 8}, {5, 7, 8}, {4, 8, 7}, {4, 7, 6}});
  const Result<ValidationReport> report = validate_solid(cube, "sliver cube");
  CHECK(report.ok());
  CHECK(signed_volume(cube) == Approx(8.0).epsilon(1e-14));
}

TEST_CASE("validation: real closed meshes validate", "[validation][real]") {
  if (!test::have_meshes()) return;
  for (const char* name : {"elephant.off", "bunny00.off", "knot1.off", "fandisk.off"}) {
    INFO(name);
    Result<Mesh> mesh = read_off(test::mesh_dir() / name);
    REQUIRE(mesh.ok());
    const Result<ValidationReport> report = validate_solid(*mesh, name);
    CHECK(report.ok());
    CHECK(is_closed_and_oriented(*mesh));
    CHECK(signed_volume(*mesh) > 0.0);
    CHECK(test::load_fixture_mesh(name).has_value());
  }
}

TEST_CASE("validation: an open real mesh is reported as not closed", "[validation][real]") {
  if (!test::have_meshes()) return;
  Result<Mesh> mesh = read_off(test::mesh_dir() / "mushroom.off");
  REQUIRE(mesh.ok());
  CHECK_THAT(error_of(*mesh, "mushroom.off"), StartsWith("mushroom.off: not closed: edge ("));
}

TEST_CASE("validation: two tetrahedra touching at one vertex get a vertex each", "[validation]") {
  // Two tetrahedra sharing only the apex (0,0,0): closed and edge-manifold, pinched at the apex.
  shatter::Mesh m;
  for (const shatter::Vec3& p : {shatter::Vec3(0, 0, 0), shatter::Vec3(1, 0, 0), shatter::Vec3(0, 1, 0),
                                 shatter::Vec3(0, 0, 1), shatter::Vec3(-1, 0, 0), shatter::Vec3(0, -1, 0),
                                 shatter::Vec3(0, 0, -1)})
    m.add_vertex(p);
  for (const shatter::Triangle& t : {shatter::Triangle{0, 2, 1}, shatter::Triangle{0, 1, 3}, shatter::Triangle{0, 3, 2},
                                     shatter::Triangle{1, 2, 3}, shatter::Triangle{0, 4, 5}, shatter::Triangle{0, 6, 4},
                                     shatter::Triangle{0, 5, 6}, shatter::Triangle{4, 6, 5}})
    m.add_triangle(t[0], t[1], t[2], shatter::FaceTag::surface);
  auto report = shatter::validate_solid(m, "pinched");
  REQUIRE(report.ok());
  CHECK(report->split_pinched_vertices == 1);
  CHECK(m.vertices.size() == 8);
  CHECK(shatter::is_closed_and_oriented(m));
  // Each apex copy is now used by exactly one tetrahedron's three faces.
  int uses_of_apex = 0;
  for (const shatter::Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) uses_of_apex += t[k] == 0;
  CHECK(uses_of_apex == 3);
}

TEST_CASE("is_closed_and_oriented agrees with the edge classification, at vertices of few and of many edges",
          "[mesh][validation]") {
  // The cylinder's cap centres have 200 edges each (the binary-search path), its rim vertices 5 or 6.
  const Mesh closed = make_cylinder(1.0, 2.0, 200);
  const auto classified_ok = [](const Mesh& m) {
    const EdgeClassification edges = classify_edges(m.triangles, m.vertices.size());
    return std::all_of(edges.state.begin(), edges.state.end(), [](EdgeState s) { return s == EdgeState::ok; });
  };
  REQUIRE(classified_ok(closed));
  CHECK(is_closed_and_oriented(closed));
  // Every single-face defect, once per face: flipped, removed, doubled. Each is found by both.
  for (std::size_t f = 0; f < closed.triangles.size(); f += 7) {
    Mesh flipped = closed;
    std::swap(flipped.triangles[f][1], flipped.triangles[f][2]);
    Mesh removed = closed;
    removed.triangles.erase(removed.triangles.begin() + static_cast<std::ptrdiff_t>(f));
    Mesh doubled = closed;
    doubled.triangles.push_back(closed.triangles[f]);
    for (const Mesh* m : {&flipped, &removed, &doubled}) {
      INFO("face " << f);
      CHECK_FALSE(classified_ok(*m));
      CHECK_FALSE(is_closed_and_oriented(*m));
    }
  }
}
