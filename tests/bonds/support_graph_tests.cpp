// Support graph: bonds found from geometry, with section properties against closed forms.
#include "algorithms/bonds/graph_components.h"
#include "algorithms/bonds/section_moments.h"
#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/mesh_io.h"
#include "fixtures/structures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

using namespace shatter;
using namespace shatter::fixtures;
using Catch::Matchers::WithinRel;

namespace {

// A box 4 (x) by b = 0.4 (y) by h = 0.6 (z), cut across x at 1, 2, 3.
const Vec3 kSize(4.0, 0.4, 0.6);
const Vec3 kCenter(2.0, 0.0, 0.0);

const Bond& bond_at_x(const SupportGraph& g, double x) {
  const auto it = std::find_if(g.bonds.begin(), g.bonds.end(),
                               [&](const Bond& e) { return std::abs(e.centroid.x() - x) < 1e-9; });
  REQUIRE(it != g.bonds.end());
  return *it;
}

void check_three_slab_bonds(const SupportGraph& g) {
  REQUIRE(g.bond_count() == 3);
  const double b = kSize.y(), h = kSize.z();
  for (const double x : {1.0, 2.0, 3.0}) {
    const Bond& e = bond_at_x(g, x);
    CHECK(e.a < e.b);
    CHECK_THAT(e.area, WithinRel(b * h, 1e-12));
    // From a to b along the axis: b's centroid lies on the normal's side.
    CHECK(std::abs(std::abs(e.normal.x()) - 1.0) < 1e-12);
    CHECK(e.normal.dot(g.nodes[static_cast<std::size_t>(e.b)].centroid - g.nodes[static_cast<std::size_t>(e.a)].centroid) > 0.0);
    CHECK(e.centroid.tail<2>().norm() < 1e-12);
    // h > b: the larger moment b h^3 / 12 is about the y axis, whose extreme fibre is h / 2 away.
    CHECK_THAT(e.moment_1, WithinRel(b * h * h * h / 12.0, 1e-10));
    CHECK_THAT(e.moment_2, WithinRel(h * b * b * b / 12.0, 1e-10));
    CHECK(std::abs(std::abs(e.axis_1.y()) - 1.0) < 1e-10);
    CHECK_THAT(e.polar_moment, WithinRel(e.moment_1 + e.moment_2, 1e-14));
    CHECK_THAT(e.fibre_1, WithinRel(h / 2.0, 1e-12));
    CHECK_THAT(e.fibre_2, WithinRel(b / 2.0, 1e-12));
    CHECK_THAT(e.radius, WithinRel(std::hypot(b, h) / 2.0, 1e-12));
    CHECK_THAT(e.length, WithinRel(1.0, 1e-12));
  }
}

}  // namespace

TEST_CASE("support-graph: box cut by 3 parallel planes has 3 cross-section bonds", "[bonds]") {
  const std::vector<Fragment> fragments = sliced_box(kSize, kCenter, planes_at(0, {1.0, 2.0, 3.0}));
  REQUIRE(fragments.size() == 4);
  const SupportGraph g = graph_of(fragments, {}, 2400.0);
  check_three_slab_bonds(g);
  for (const SupportNode& n : g.nodes) CHECK_THAT(n.mass, WithinRel(2400.0 * 0.24, 1e-12));
  // The seed's CalculateConnections test: pieces in a line have 1, 2, ..., 2, 1 connections.
  int ends = 0;
  for (const auto& list : g.node_bonds) ends += list.size() == 1 ? 1 : 0;
  CHECK(ends == 2);
}

TEST_CASE("support-graph: bonds survive writing and re-reading the fragments", "[bonds]") {
  const std::vector<Fragment> fragments = sliced_box(kSize, kCenter, planes_at(0, {1.0, 2.0, 3.0}));
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "shatter_support_graph_test";
  std::filesystem::create_directories(dir);
  for (const char* ext : {".obj", ".off"}) {  // OBJ keeps the cut tags, OFF loses them (all faces offered)
    std::vector<Mesh> meshes;
    for (std::size_t i = 0; i < fragments.size(); ++i) {
      const std::filesystem::path path = dir / ("fragment_" + std::to_string(i) + ext);
      const bool obj = std::string(ext) == ".obj";
      const Status written = obj ? write_obj(fragments[i].mesh, path) : write_off(fragments[i].mesh, path);
      REQUIRE(written.ok());
      Result<Mesh> read = read_mesh(path);
      REQUIRE(read.ok());
      meshes.push_back(std::move(read.value()));
    }
    Result<SupportGraph> g = build_support_graph(meshes, {}, {});
    REQUIRE(g.ok());
    check_three_slab_bonds(*g);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("support-graph: a later cut splits one side's face into two bonds", "[bonds]") {
  // Cut at x = 2, then only the right half across y = 0.05: the left cap is one face set, the right
  // caps another triangulation; the overlaps must add up to the cross-section.
  std::vector<Fragment> halves = sliced_box(kSize, kCenter, planes_at(0, {2.0}));
  REQUIRE(halves.size() == 2);
  const std::size_t right = halves[0].mass.centroid.x() > 2.0 ? 0 : 1;
  Plane split;
  split.point = Vec3(0.0, 0.05, 0.0);
  split.normal = Vec3::UnitY();
  const PlaneSliceFracturer slicer;
  Result<std::vector<Fragment>> quarters = slicer.fracture_by_planes(halves[right].mesh, std::vector<Plane>{split});
  REQUIRE(quarters.ok());
  std::vector<Fragment> all = {halves[1 - right]};
  for (Fragment& f : *quarters) all.push_back(f);
  const SupportGraph g = graph_of(all, {}, 1000.0);
  REQUIRE(g.bond_count() == 3);  // left-right top, left-right bottom, right top-bottom
  double across_x = 0.0;
  for (const Bond& e : g.bonds) {
    if (std::abs(std::abs(e.normal.x()) - 1.0) < 1e-9) {
      across_x += e.area;
      // Each part of the split face is a rectangle 0.6 high: I about the y axis = w h^3 / 12.
      const double w = e.area / 0.6;
      CHECK_THAT(std::max(e.moment_1, e.moment_2), WithinRel(std::max(w * 0.216 / 12.0, 0.6 * w * w * w / 12.0), 1e-9));
    } else {
      CHECK_THAT(e.area, WithinRel(2.0 * 0.6, 1e-12));  // the y cut: 2 long, 0.6 high
    }
  }
  CHECK_THAT(across_x, WithinRel(0.4 * 0.6, 1e-12));
}

TEST_CASE("support-graph: anchors fix exactly the fragments they overlap", "[bonds]") {
  const std::vector<Fragment> fragments = sliced_box(kSize, kCenter, planes_at(0, {1.0, 2.0, 3.0}));
  const SupportGraph g = graph_of(fragments, {box_region({-1, -1, -1}, {0.001, 1, 1})}, 2400.0);
  for (const SupportNode& n : g.nodes) CHECK(n.anchored == (n.centroid.x() < 1.0));
  const GraphComponents c = graph_components(g);
  CHECK(c.nodes.size() == 1);
  CHECK(falling_clusters(c).empty());
}

TEST_CASE("support-graph: bad settings and geometry are errors", "[bonds]") {
  const std::vector<Fragment> fragments = sliced_box(kSize, kCenter, planes_at(0, {2.0}));
  SupportGraphSettings bad;
  bad.density = -1.0;
  CHECK_FALSE(build_support_graph(fragments, {}, bad).ok());
  bad = {};
  bad.relative_tolerance = 0.0;
  CHECK_FALSE(build_support_graph(fragments, {}, bad).ok());
  const std::vector<Aabb> inverted = {box_region({0, 0, 0}, {1, 1, 1})};
  std::vector<Aabb> wrong = inverted;
  wrong[0].min.x() = 2.0;
  CHECK_FALSE(build_support_graph(fragments, wrong, {}).ok());
  std::vector<Fragment> nan = fragments;
  nan[0].mesh.vertices[0].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(build_support_graph(nan, {}, {}).ok());
}

TEST_CASE("section-moments: rotated rectangle has the closed-form principal moments", "[bonds]") {
  const double w = 3.0, t = 1.0, angle = 0.3;
  const Vec2 ax(std::cos(angle), std::sin(angle)), ay(-std::sin(angle), std::cos(angle));
  const Vec2 c(5.0, -2.0);
  const std::vector<Vec2> rect = {c - 0.5 * w * ax - 0.5 * t * ay, c + 0.5 * w * ax - 0.5 * t * ay,
                                  c + 0.5 * w * ax + 0.5 * t * ay, c - 0.5 * w * ax + 0.5 * t * ay};
  AreaMoments m;
  m.add_polygon(rect);
  const PrincipalSection s = principal_section(m);
  CHECK_THAT(m.area, WithinRel(w * t, 1e-13));
  CHECK((s.centroid - c).norm() < 1e-12);
  CHECK_THAT(s.moment_1, WithinRel(t * w * w * w / 12.0, 1e-11));  // about the short direction
  CHECK_THAT(s.moment_2, WithinRel(w * t * t * t / 12.0, 1e-11));
  CHECK(std::abs(std::abs(s.axis_1.dot(ay)) - 1.0) < 1e-12);
  // Clipping: two overlapping unit squares shifted by (0.5, 0.25) share 0.5 x 0.75.
  const std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Vec2> moved = {{0.5, 0.25}, {1.5, 0.25}, {1.5, 1.25}, {0.5, 1.25}};
  AreaMoments overlap;
  overlap.add_polygon(clip_convex(sq, moved));
  CHECK_THAT(overlap.area, WithinRel(0.375, 1e-14));
}
