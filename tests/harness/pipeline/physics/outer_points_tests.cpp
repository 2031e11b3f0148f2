// outer_point_indices against truths known without it: a box whose faces are grids keeps exactly its
// 8 corners; a sphere keeps every point; the pieces of real fractures keep a hull of the same volume
// as all their points (Bullet's hull computer, convex_hull_volume) with fewer points; a point moved off
// its face by far less than a float's resolution at the box's size is a corner again and is kept.
// In the physics world, colliders without the dropped points stay inside their pieces where the
// margin inset left points of the others outside, and trajectories stay as close as Bullet's own
// spread (the same bodies added in another order).

#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "algorithms/core/convex_hull_volume.h"
#include "harness/pipeline/physics/outer_points.h"
#include "tests/support/shapes.h"
#include "tests/support/standing_block.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

using namespace shatter;

namespace {

/// A box [0, size] whose every face is an n x n grid of quads (two triangles each), the grid points of
/// neighbouring faces shared: 8 corners, 12 (n - 1) points on the edges' straight runs and 6 (n - 1)^2
/// inside the faces.
Mesh grid_box(const Vec3& size, int n) {
  Mesh m;
  std::map<std::array<int, 3>, std::int32_t> index;
  const auto vertex = [&](std::array<int, 3> g) {
    const auto [it, fresh] = index.try_emplace(g, static_cast<std::int32_t>(m.vertices.size()));
    if (fresh) m.add_vertex(Vec3(size.x() * g[0] / n, size.y() * g[1] / n, size.z() * g[2] / n));
    return it->second;
  };
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3;
    const int v = (a + 2) % 3;  // e_u x e_v = e_a
    for (const int side : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<std::int32_t, 4> q{};
          const std::array<std::array<int, 2>, 4> uv{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> g{};
            g[a] = side;
            g[u] = uv[k][0];
            g[v] = uv[k][1];
            q[k] = vertex(g);
          }
          if (side == n) {  // faces +e_a
            m.add_triangle(q[0], q[1], q[2], FaceTag::surface);
            m.add_triangle(q[0], q[2], q[3], FaceTag::surface);
          } else {
            m.add_triangle(q[0], q[2], q[1], FaceTag::surface);
            m.add_triangle(q[0], q[3], q[2], FaceTag::surface);
          }
        }
  }
  return m;
}

std::vector<Vec3> positions(const Mesh& mesh, const std::vector<std::int32_t>& indices) {
  std::vector<Vec3> out;
  for (const std::int32_t v : indices) out.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  return out;
}

}  // namespace

TEST_CASE("outer points: a box with grid faces keeps its 8 corners and nothing else", "[physics][colliders]") {
  const Vec3 size(2.0, 1.0, 0.5);
  const Mesh box = grid_box(size, 4);
  REQUIRE(box.vertices.size() == 8 + 12 * 3 + 6 * 9);
  const std::vector<std::int32_t> kept = outer_point_indices(box, vertex_planes(box));
  REQUIRE(kept.size() == 8);
  std::set<std::array<double, 3>> corners;
  for (const Vec3& p : positions(box, kept)) corners.insert({p.x(), p.y(), p.z()});
  for (const double x : {0.0, size.x()})
    for (const double y : {0.0, size.y()})
      for (const double z : {0.0, size.z()}) CHECK(corners.count({x, y, z}) == 1);
}

TEST_CASE("outer points: a point lifted off its face is a corner again and stays", "[physics][colliders]") {
  Mesh box = grid_box(Vec3(1.0, 1.0, 1.0), 4);
  // The grid point (2, 2, 4) / 4: the middle of the top face. Lifted by 1e-7 of the box's size (below a
  // float's resolution at 1 m, a hundred times the tolerance), it is the hull's apex.
  std::size_t middle = box.vertices.size();
  for (std::size_t i = 0; i < box.vertices.size(); ++i)
    if ((box.vertices[i] - Vec3(0.5, 0.5, 1.0)).norm() < 1e-12) middle = i;
  REQUIRE(middle < box.vertices.size());
  box.vertices[middle].z() += 1e-7;
  const std::vector<std::int32_t> kept = outer_point_indices(box, vertex_planes(box));
  CHECK(kept.size() == 9);
  CHECK(std::count(kept.begin(), kept.end(), static_cast<std::int32_t>(middle)) == 1);
  // Pushed in by as much, it is inside the hull: dropping it would be exact, but it is not within the
  // tolerance of its face's plane, and a point in doubt is kept.
  box.vertices[middle].z() -= 2e-7;
  CHECK(outer_point_indices(box, vertex_planes(box)).size() == 9);
}

TEST_CASE("outer points: a sphere's points are all corners", "[physics][colliders]") {
  const Mesh sphere = make_sphere(0.8, 24, 12, Vec3(1, 2, 3));
  CHECK(outer_point_indices(sphere, vertex_planes(sphere)).size() == sphere.vertices.size());
}

TEST_CASE("outer points: fracture pieces keep the hull of all their points with fewer points", "[physics][colliders]") {
  // Convex and non-convex solids, cut by plane slicing (pieces crossed by later cuts carry points on
  // their edges) and by Voronoi cells.
  const std::vector<Mesh> solids = {make_box(Vec3(2.0, 1.0, 0.3), Vec3(5, -3, 1)), test::make_u_shape(),
                                    make_cylinder(0.5, 2.0, 24)};
  FractureParams params;
  params.fragments = 25;
  params.seed = 3;
  std::size_t all_points = 0;
  std::size_t kept_points = 0;
  double worst = 0.0;
  for (const Mesh& solid : solids)
    for (const bool voronoi : {false, true}) {
      auto pieces = voronoi ? VoronoiFracturer().fracture(solid, params) : PlaneSliceFracturer().fracture(solid, params);
      REQUIRE(pieces.ok());
      REQUIRE(pieces->size() > 5);
      for (const Fragment& piece : *pieces) {
        const std::vector<std::int32_t> kept = outer_point_indices(piece.mesh, vertex_planes(piece.mesh));
        const double full = convex_hull_volume(piece.mesh.vertices);
        REQUIRE(full > 0.0);
        worst = std::max(worst, std::abs(convex_hull_volume(positions(piece.mesh, kept)) - full) / full);
        CHECK(std::is_sorted(kept.begin(), kept.end()));
        all_points += piece.mesh.vertices.size();
        kept_points += kept.size();
      }
    }
  INFO("points " << all_points << ", kept " << kept_points << ", largest relative change of hull volume " << worst);
  CHECK(worst <= 1e-12);
  CHECK(kept_points < all_points);
}

TEST_CASE("outer points: every vertex's planes and neighbours", "[physics][colliders]") {
  const Mesh cube = test::make_unit_cube();  // 8 corners, each on 3 planes
  const VertexPlanes planes = vertex_planes(cube);
  for (std::size_t v = 0; v < cube.vertices.size(); ++v) {
    CHECK(planes.normals_of(v).size() == 3);
    for (const Vec3& n : planes.normals_of(v)) CHECK(n.norm() == Approx(1.0).epsilon(1e-15));
    CHECK(planes.ring_of(v).size() % 2 == 0);
    CHECK(std::count(planes.ring_of(v).begin(), planes.ring_of(v).end(), static_cast<std::int32_t>(v)) == 0);
  }
}

namespace {

/// How far the points of `body`'s collider reach beyond the inside of every face plane of `piece`
/// (convex) moved in by the margin, m: at most round-off when the collider plus its margin stays within
/// the piece.
double reach_beyond_inset(const PhysicsWorld& world, int body, const Fragment& piece) {
  const double margin = world.settings().collision_margin;
  double worst = -HUGE_VAL;
  for (const Vec3& p : world.collider_points(body))
    for (const Triangle& t : piece.mesh.triangles) {
      const Vec3& a = piece.mesh.vertices[static_cast<std::size_t>(t[0])];
      const Vec3 n = (piece.mesh.vertices[static_cast<std::size_t>(t[1])] - a)
                         .cross(piece.mesh.vertices[static_cast<std::size_t>(t[2])] - a);
      if (!(n.norm() > 1e-12)) continue;
      worst = std::max(worst, n.normalized().dot(p - a) + margin);
    }
  return worst;
}

}  // namespace

TEST_CASE("outer points: colliders stay inside the pieces' inset, trajectories as close as another body order",
          "[physics][colliders]") {
  // The block of 60 convex slabs of the tight-hull test; the slabs cut after others carry points on
  // their edges. Each point is moved in along its faces' normals by the margin; a point on an edge's
  // straight run near a corner then lands beyond the corner's own inset, so with every point the
  // collider plus its margin bulges out of the piece, into its neighbours. Without those points it
  // stays inside: the collider is a subset of the one with every point, its contacts a subset of those.
  const std::vector<Fragment> slabs = test::block_slices();
  std::size_t points = 0;
  std::size_t kept = 0;
  for (const Fragment& f : slabs) {
    points += f.mesh.vertices.size();
    kept += outer_point_indices(f.mesh, vertex_planes(f.mesh)).size();
  }
  REQUIRE(kept < points);
  PhysicsSettings every_point;
  every_point.drop_inner_points = false;
  PhysicsSettings outer_only;
  outer_only.drop_inner_points = true;
  // Pieces whose collider plus margin stays within the piece (to float round-off at metre
  // coordinates). An acute corner, whose inset is capped (physics_world.cpp), can reach out either way.
  int inside_all = 0;
  int inside_outer = 0;
  {
    PhysicsWorld all_world(every_point);
    PhysicsWorld outer_world(outer_only);
    for (const Fragment& f : slabs) {
      const double all_beyond = reach_beyond_inset(all_world, all_world.add_fragment(f, 2400.0), f);
      const double outer_beyond = reach_beyond_inset(outer_world, outer_world.add_fragment(f, 2400.0), f);
      inside_all += all_beyond <= 1e-6 ? 1 : 0;
      inside_outer += outer_beyond <= 1e-6 ? 1 : 0;
      CHECK(outer_beyond <= all_beyond);
    }
  }
  INFO(points << " points, " << kept << " kept; pieces whose collider stays inside: with every point "
              << inside_all << ", outer points only " << inside_outer << " of " << slabs.size());
  CHECK(4 * inside_outer >= 3 * static_cast<int>(slabs.size()));
  CHECK(4 * inside_all <= static_cast<int>(slabs.size()));
  for (const int steps : {1, 30}) {
    const test::SteppedBlock all = test::stand_block(slabs, every_point, false, steps);
    const test::SteppedBlock outer = test::stand_block(slabs, outer_only, false, steps);
    const test::SteppedBlock reordered = test::stand_block(slabs, every_point, true, steps);
    const double by_points = test::largest_difference(all.positions, outer.positions);
    const double by_order = test::largest_difference(all.positions, reordered.positions);
    INFO(steps << " steps: touching pairs " << all.touching.size() << " with every point, " << outer.touching.size()
               << " outer only; largest difference from the points " << by_points << " m, from the order "
               << by_order << " m");
    if (steps == 1) {
      REQUIRE(all.touching.size() > 100);
      const auto has = [&](const TouchingPair& p) {
        return std::any_of(all.touching.begin(), all.touching.end(),
                           [&](const TouchingPair& q) { return q.first == p.first && q.second == p.second; });
      };
      CHECK(std::all_of(outer.touching.begin(), outer.touching.end(), has));
    } else {
      CHECK(by_points <= 2.0 * by_order);
    }
    CHECK(by_order > 0.0);
  }
}
