#include "harness/metrics/fracture_metrics.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace shatter {
namespace {

// Faces of a box, in the order used by make_tagged_box.
enum BoxFace { kMinX = 0, kMaxX, kMinY, kMaxY, kMinZ, kMaxZ };

// Outward box [lo, hi] (12 triangles); the faces listed in `cut_faces` are tagged cut, the rest
// surface. Corner i has x from bit 0, y from bit 1, z from bit 2.
Mesh make_tagged_box(const Vec3& lo, const Vec3& hi, std::vector<BoxFace> cut_faces = {}) {
  Mesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.add_vertex({(i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z()});
  // Quads counter-clockwise seen from outside, one per BoxFace.
  const std::array<std::array<int, 4>, 6> quads = {{
      {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
  for (int f = 0; f < 6; ++f) {
    bool cut = false;
    for (BoxFace c : cut_faces) cut = cut || c == f;
    const FaceTag tag = cut ? FaceTag::cut : FaceTag::surface;
    const std::array<int, 4>& q = quads[static_cast<std::size_t>(f)];
    mesh.add_triangle(q[0], q[1], q[2], tag);
    mesh.add_triangle(q[0], q[2], q[3], tag);
  }
  return mesh;
}

// A fragment with its analytic volume (not computed by the code under test).
Fragment box_fragment(const Vec3& lo, const Vec3& hi, std::vector<BoxFace> cut_faces = {}) {
  Fragment fragment;
  fragment.mesh = make_tagged_box(lo, hi, std::move(cut_faces));
  fragment.mass.volume = (hi - lo).prod();
  fragment.mass.centroid = 0.5 * (lo + hi);
  return fragment;
}

MassProperties unit_box_mass() {
  MassProperties mass;
  mass.volume = 1.0;
  mass.centroid = Vec3::Constant(0.5);
  return mass;
}

// 4 standard deviations of a share estimated from n Bernoulli(p) samples.
double four_sigma(double p, int n) { return 4.0 * std::sqrt(p * (1.0 - p) / n); }

constexpr double kTol = 1e-12;

}  // namespace

TEST_CASE("fracture-metrics: unit box cut at x = 0.3 into two boxes is exact", "[fracture-metrics]") {
  const Mesh input = make_tagged_box({0, 0, 0}, {1, 1, 1});
  const std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {0.3, 1, 1}, {kMaxX}),
                                           box_fragment({0.3, 0, 0}, {1, 1, 1}, {kMinX})};
  const FractureMetrics m = fracture_metrics(input, unit_box_mass(), fragments, 2);
  CHECK(m.volume_error == Approx(0.0).margin(kTol));
  CHECK(m.all_closed);
  CHECK(m.partition_samples == 2000);  // the box fills its bounding box: every draw is inside
  CHECK(m.partition_error == 0.0);
  // Surface-tagged area: 2.2 + 3.8 = 6, the input's area; the two cut faces do not count.
  CHECK(m.area_error == Approx(0.0).margin(kTol));
  CHECK(m.min_fragment_volume == Approx(0.3).margin(kTol));
  CHECK(m.fragment_count == 2);
  CHECK(m.requested == 2);
}

TEST_CASE("fracture-metrics: two copies of the box overlap everywhere", "[fracture-metrics]") {
  const Mesh input = make_tagged_box({0, 0, 0}, {1, 1, 1});
  const std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {1, 1, 1}), box_fragment({0, 0, 0}, {1, 1, 1})};
  const FractureMetrics m = fracture_metrics(input, unit_box_mass(), fragments, 2);
  CHECK(m.partition_error == 1.0);
  CHECK(m.volume_error == Approx(1.0).margin(kTol));
  CHECK(m.area_error == Approx(1.0).margin(kTol));
  CHECK(m.all_closed);
}

TEST_CASE("fracture-metrics: a missing fragment leaves 70 percent uncovered", "[fracture-metrics]") {
  const Mesh input = make_tagged_box({0, 0, 0}, {1, 1, 1});
  const std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {0.3, 1, 1}, {kMaxX})};
  const FractureMetrics m = fracture_metrics(input, unit_box_mass(), fragments, 2);
  REQUIRE(m.partition_samples == 2000);
  CHECK(m.partition_error == Approx(0.7).margin(four_sigma(0.7, 2000)));
  CHECK(m.volume_error == Approx(0.7).margin(kTol));
  CHECK(m.area_error == Approx((6.0 - 2.2) / 6.0).margin(kTol));
  CHECK(m.all_closed);
  CHECK(m.fragment_count == 1);
  CHECK(m.requested == 2);
}

TEST_CASE("fracture-metrics: a fragment with a flipped triangle is not closed", "[fracture-metrics]") {
  const Mesh input = make_tagged_box({0, 0, 0}, {1, 1, 1});
  std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {0.3, 1, 1}, {kMaxX}),
                                     box_fragment({0.3, 0, 0}, {1, 1, 1}, {kMinX})};
  std::swap(fragments[1].mesh.triangles[5][1], fragments[1].mesh.triangles[5][2]);
  CHECK_FALSE(fracture_metrics(input, unit_box_mass(), fragments, 2).all_closed);
}

TEST_CASE("fracture-metrics: a fragment with non-positive volume is not valid", "[fracture-metrics]") {
  const Mesh input = make_tagged_box({0, 0, 0}, {1, 1, 1});
  std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {1, 1, 1})};
  fragments[0].mass.volume = -1.0;
  const FractureMetrics m = fracture_metrics(input, unit_box_mass(), fragments, 1);
  CHECK_FALSE(m.all_closed);
  CHECK(m.volume_error == Approx(2.0).margin(kTol));
  CHECK(m.min_fragment_volume == -1.0);
}

TEST_CASE("fracture-metrics: no fragments, no volume and no samples stay finite", "[fracture-metrics]") {
  const Mesh input = make_tagged_box({0, 0, 0}, {1, 1, 1});
  SECTION("no fragments: everything uncovered") {
    const FractureMetrics m = fracture_metrics(input, unit_box_mass(), {}, 5);
    CHECK(m.partition_error == 1.0);
    CHECK(m.volume_error == Approx(1.0).margin(kTol));
    CHECK(m.area_error == Approx(1.0).margin(kTol));
    CHECK(m.min_fragment_volume == 0.0);
    CHECK(m.fragment_count == 0);
    CHECK(m.all_closed);
  }
  SECTION("zero input volume and area: the relative errors are 0") {
    const std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {1, 1, 1})};
    const FractureMetrics m = fracture_metrics(Mesh{}, MassProperties{}, fragments, 1);
    CHECK(m.volume_error == 0.0);
    CHECK(m.area_error == 0.0);
    CHECK(m.partition_samples == 0);
    CHECK(m.partition_error == 0.0);
  }
  SECTION("zero samples requested") {
    FractureMetricsOptions options;
    options.partition_samples = 0;
    const FractureMetrics m = fracture_metrics(input, unit_box_mass(), {}, 1, options);
    CHECK(m.partition_samples == 0);
    CHECK(m.partition_error == 0.0);
  }
  SECTION("a non-finite fragment volume gives the largest finite error") {
    std::vector<Fragment> fragments = {box_fragment({0, 0, 0}, {1, 1, 1})};
    fragments[0].mass.volume = std::nan("");
    const FractureMetrics m = fracture_metrics(input, unit_box_mass(), fragments, 1);
    CHECK(std::isfinite(m.volume_error));
    CHECK(m.volume_error > 1e300);
    CHECK(std::isfinite(m.min_fragment_volume));
    CHECK_FALSE(m.all_closed);
  }
}

TEST_CASE("fracture-metrics: a thin shell fills little of its box and the sampling gives up",
          "[fracture-metrics]") {
  // Hollow cube: outer [0,1]^3, cavity [t, 1-t]^3 (inward). Its share of the bounding box is
  // 1 - (1 - 2t)^3 ~ 6t = 0.006, so 50 x 2000 draws find about 600 inside points.
  const double t = 0.001;
  Mesh shell = make_tagged_box({0, 0, 0}, {1, 1, 1});
  const Mesh cavity = make_tagged_box(Vec3::Constant(t), Vec3::Constant(1 - t));
  const auto offset = static_cast<std::int32_t>(shell.vertices.size());
  for (const Vec3& p : cavity.vertices) shell.add_vertex(p);
  for (const Triangle& tri : cavity.triangles)
    shell.add_triangle(tri[0] + offset, tri[2] + offset, tri[1] + offset, FaceTag::surface);
  MassProperties mass;
  mass.volume = 1.0 - std::pow(1.0 - 2.0 * t, 3);
  Fragment whole;
  whole.mesh = shell;
  whole.mass = mass;

  const std::vector<Fragment> fragments = {whole};
  const FractureMetrics m = fracture_metrics(shell, mass, fragments, 1);
  const double expected = 2000.0 * 50.0 * mass.volume;  // binomial mean of the inside draws
  CHECK(m.partition_samples == Approx(expected).margin(4.0 * std::sqrt(expected)));
  CHECK(m.partition_samples < 2000);
  CHECK(m.partition_error == 0.0);
  CHECK(m.volume_error == 0.0);
  CHECK(m.area_error == 0.0);
  CHECK(m.all_closed);
}

}  // namespace shatter
