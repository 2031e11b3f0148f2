// The hull pair test with kept separating axes (hull_pair_collision.h) answers most tests of a pile
// of falling pieces without GJK, and changes no trajectory: every body's position and rotation in
// every step is the same, bit for bit, as with Bullet's own convex-convex test. The narrow phase on
// worker threads (narrow_phase_dispatcher.h) changes none either.

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/pipeline/physics/physics_world.h"
#include "harness/pipeline/workers.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <vector>

namespace {

using shatter::Fragment;
using shatter::PhysicsSettings;
using shatter::PhysicsWorld;
using shatter::Vec3;

std::vector<Fragment> slices(const Vec3& size, int n, std::uint64_t seed) {
  shatter::FractureParams params;
  params.fragments = n;
  params.seed = seed;
  auto out = shatter::PlaneSliceFracturer().fracture(shatter::make_box(size), params);
  REQUIRE(out.ok());
  return std::move(*out);
}

/// The fragment moved away from the origin by `spread` times its centroid, then by `lift`.
Fragment spread_out(Fragment f, double spread, const Vec3& lift) {
  const Vec3 offset = (spread - 1.0) * f.mass.centroid + lift;
  for (Vec3& v : f.mesh.vertices) v += offset;
  f.mass = shatter::mass_properties(f.mesh);
  return f;
}

struct Run {
  std::vector<Vec3> positions;             ///< every body, every step
  std::vector<Eigen::Matrix3d> rotations;  ///< every body, every step
  shatter::HullPairCounts counts;
  int peak_pairs = 0;
};

/// Sixty slabs of a 2 x 1 x 1 m block spread apart and dropped, four of them knocked, with a compound
/// of three pieces of another block falling onto them, on the ground and on a static pedestal.
Run drop_pile(bool keep_axes, int threads = 1) {
  PhysicsSettings s;
  s.ground = true;
  s.keep_separating_axes = keep_axes;
  shatter::Workers workers(threads);
  PhysicsWorld world(s);
  world.set_workers(&workers);
  std::vector<int> ids;
  ids.push_back(world.add_fragment(spread_out(slices(Vec3(1, 1, 0.4), 1, 1)[0], 1.0, Vec3(0, 0, 0.2)), 2400.0, true));
  const std::vector<Fragment> pieces = slices(Vec3(2, 1, 1), 60, 7);
  for (const Fragment& f : pieces) ids.push_back(world.add_fragment(spread_out(f, 1.25, Vec3(0, 0, 1.2)), 2400.0));
  std::vector<Fragment> cluster = slices(Vec3(0.6, 0.6, 0.6), 3, 5);
  for (Fragment& f : cluster) f = spread_out(f, 1.0, Vec3(0.1, 0.2, 3.0));
  ids.push_back(world.add_cluster(cluster, 2400.0));
  for (int k = 1; k <= 4; ++k) {
    const Fragment& f = pieces[static_cast<std::size_t>(15 * k - 1)];
    world.apply_impulse(ids[static_cast<std::size_t>(15 * k)], Vec3(30.0 * k, -40.0, 20.0),
                        spread_out(f, 1.25, Vec3(0, 0, 1.2)).mass.centroid + Vec3(0.05, 0.05, 0.0));
  }
  Run run;
  for (int step = 0; step < 150; ++step) {
    world.step();
    run.peak_pairs = std::max(run.peak_pairs, world.overlapping_pairs());
    for (const int id : ids) {
      run.positions.push_back(world.position(id));
      run.rotations.push_back(world.rotation(id));
    }
  }
  run.counts = world.hull_pair_counts();
  return run;
}

}  // namespace

TEST_CASE("hull pairs: kept separating axes skip most tests and change no trajectory", "[physics]") {
  const Run bullet = drop_pile(false);
  const Run kept = drop_pile(true);
  CHECK(bullet.counts.tests == 0);  // Bullet's own algorithm ran
  REQUIRE(kept.counts.tests > 0);
  INFO("tests " << kept.counts.tests << ", skipped " << kept.counts.skipped << ", probed " << kept.counts.probed
                 << ", first tests apart " << kept.counts.first_apart);
  // Most pairs of the pile are apart and stay apart: the kept axis answers them.
  CHECK(kept.counts.skipped > kept.counts.tests / 2);
  CHECK(kept.counts.probed > 0);
  // The pieces start spread apart: many pairs' first tests are answered without GJK.
  CHECK(kept.counts.first_apart > 0);
  CHECK(kept.counts.first_apart <= kept.counts.probed);
  CHECK(bullet.peak_pairs == kept.peak_pairs);
  REQUIRE(bullet.positions.size() == kept.positions.size());
  CHECK(bullet.positions == kept.positions);
  CHECK(bullet.rotations == kept.rotations);
  // The pieces fell and met: the comparison is of bodies in motion and in contact.
  CHECK(bullet.peak_pairs > 200);
  CHECK((bullet.positions.back() - bullet.positions[bullet.positions.size() / 150 - 1]).norm() > 0.5);
}

TEST_CASE("hull pairs: the narrow phase on worker threads changes no trajectory", "[physics][threads]") {
  const Run one = drop_pile(true, 1);
  for (const int threads : {2, 3}) {
    INFO(threads << " threads");
    const Run many = drop_pile(true, threads);
    CHECK(many.counts.tests == one.counts.tests);
    CHECK(many.counts.skipped == one.counts.skipped);
    CHECK(many.counts.probed == one.counts.probed);
    CHECK(many.counts.first_apart == one.counts.first_apart);
    CHECK(many.peak_pairs == one.peak_pairs);
    CHECK(many.positions == one.positions);
    CHECK(many.rotations == one.rotations);
  }
  // Bullet's own pair test on workers as well.
  CHECK(drop_pile(false, 2).positions == drop_pile(false, 1).positions);
}
