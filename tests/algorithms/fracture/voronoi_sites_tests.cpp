// Where the Voronoi sites go around an impact (voronoi_sites.h): the sampler draws each distribution
// only where it can reach the solid's box, and the sites must follow the law of draws from the whole
// ball (uniform) and shell (density 1 / d^2 for d in [r, D]). The reference here is that law drawn
// literally, as the definition says (a uniform distance in the shell, a uniform direction, rejection
// outside the solid); the two samples are compared by two-sample Kolmogorov-Smirnov statistics on the
// distance from the impact and on each coordinate, at the 0.1 % level (the seeds are fixed, so the
// outcome is deterministic). Three placements exercise the three ways the shell is drawn: a piece far
// from the impact (the cone of its box), one across the ball's boundary (its box, kept by 1 / d^2), an
// impact inside a large solid (the whole shell).
#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/fracture/voronoi/point_in_mesh.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

using namespace shatter;

namespace {

/// The sites of the definition: `near` uniform in B(c, r), the rest at a uniform distance in [r, far]
/// in a uniform direction, each kept when strictly inside the solid.
std::vector<Vec3> reference_sites(const PointInMesh& inside, const Vec3& c, double r, int near, int total,
                                  std::uint64_t seed) {
  SplitMix64 rng(seed);
  const Aabb& box = inside.bounds();
  double far = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
                      (k & 4) ? box.max.z() : box.min.z());
    far = std::max(far, (corner - c).norm());
  }
  std::vector<Vec3> out;
  long long draws = 0;
  while (static_cast<int>(out.size()) < total && ++draws < 200'000'000) {
    const bool in_ball = static_cast<int>(out.size()) < near;
    const double distance = in_ball ? r * std::cbrt(rng.uniform()) : rng.uniform(r, far);
    const Vec3 q = c + distance * rng.unit_vector();
    if (inside(q) == InsideAnswer::inside) out.push_back(q);
  }
  REQUIRE(static_cast<int>(out.size()) == total);
  return out;
}

/// The two-sample Kolmogorov-Smirnov statistic of `a` and `b` (sorted copies).
double ks_statistic(std::vector<double> a, std::vector<double> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::size_t i = 0, j = 0;
  double worst = 0.0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    worst = std::max(worst, std::abs(static_cast<double>(i) / a.size() - static_cast<double>(j) / b.size()));
  }
  return worst;
}

/// The KS critical value at the 0.1 % level for samples of n and m.
double ks_critical(std::size_t n, std::size_t m) {
  return 1.949 * std::sqrt(static_cast<double>(n + m) / (static_cast<double>(n) * static_cast<double>(m)));
}

/// Samples `count` sites with sample_sites in calls of `per_call` (seeds 1, 2, ...).
std::vector<Vec3> sampled_sites(const PointInMesh& inside, const Impact& impact, int per_call, int count) {
  std::vector<Vec3> out;
  for (std::uint64_t seed = 1; static_cast<int>(out.size()) < count; ++seed) {
    FractureParams params;
    params.fragments = per_call;
    params.seed = seed;
    params.impact = impact;
    auto sites = sample_sites(inside, params);
    REQUIRE(sites.ok());
    REQUIRE(static_cast<int>(sites->size()) == per_call);
    out.insert(out.end(), sites->begin(), sites->end());
  }
  return out;
}

void check_same_law(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& c) {
  const double critical = ks_critical(a.size(), b.size());
  const std::vector<std::function<double(const Vec3&)>> features = {
      [&](const Vec3& p) { return (p - c).norm(); }, [](const Vec3& p) { return p.x(); },
      [](const Vec3& p) { return p.y(); }, [](const Vec3& p) { return p.z(); }};
  for (const auto& feature : features) {
    std::vector<double> fa, fb;
    for (const Vec3& p : a) fa.push_back(feature(p));
    for (const Vec3& p : b) fb.push_back(feature(p));
    CHECK(ks_statistic(fa, fb) < critical);
  }
}

/// One call of 2000 sites around `impact` in `solid` (half in the ball, impact_share 0.5, the rest from
/// the shell) against the definition's 2000, the ball's and the shell's sites compared apart.
void check_ball_and_shell(const Mesh& solid, const Vec3& point, double radius, std::uint64_t reference_seed) {
  const PointInMesh inside(solid);
  Impact impact;
  impact.point = point;
  impact.radius = radius;
  const std::vector<Vec3> sampled = sampled_sites(inside, impact, 2000, 2000);
  const std::vector<Vec3> reference = reference_sites(inside, point, radius, 1000, 2000, reference_seed);
  const auto half = [](const std::vector<Vec3>& v, bool first) {
    return first ? std::vector<Vec3>(v.begin(), v.begin() + 1000) : std::vector<Vec3>(v.begin() + 1000, v.end());
  };
  for (const Vec3& p : half(sampled, true)) CHECK((p - point).norm() <= radius);
  for (const Vec3& p : half(sampled, false)) CHECK((p - point).norm() >= radius);
  check_same_law(half(sampled, true), half(reference, true), point);
  check_same_law(half(sampled, false), half(reference, false), point);
}

}  // namespace

TEST_CASE("voronoi sites: around a far impact they follow the law of the whole shell", "[voronoi]") {
  // A small piece 3 m from the impact: only the shell reaches it (the cone of its box is drawn).
  const Mesh piece = make_box(Vec3(0.6, 0.3, 0.4), Vec3(3.0, 0.5, -0.2));
  const PointInMesh inside(piece);
  Impact impact;
  impact.point = Vec3(0.0, 0.0, 0.0);
  impact.direction = Vec3(1.0, 0.0, 0.0);
  impact.radius = 1.0;
  const std::vector<Vec3> sampled = sampled_sites(inside, impact, 25, 5000);
  const std::vector<Vec3> reference = reference_sites(inside, impact.point, impact.radius, 0, 5000, 99);
  for (const Vec3& p : sampled) CHECK(inside(p) == InsideAnswer::inside);
  check_same_law(sampled, reference, impact.point);
  // The law is not the uniform one in the box (which the test would otherwise not tell apart): the
  // near side of the piece holds more sites than the far side.
  const auto nearer = std::count_if(sampled.begin(), sampled.end(), [](const Vec3& p) { return p.x() < 3.0; });
  CHECK(nearer > 0.55 * static_cast<double>(sampled.size()));
}

TEST_CASE("voronoi sites: a piece the impact's ball reaches gets the law of the whole ball and shell", "[voronoi]") {
  // A piece across the ball's boundary, reaching from 0.3 to 1.33 m of the impact: the ball is drawn
  // in its part of the piece's box, the shell in the box (its density falls by 7 times over the piece).
  check_ball_and_shell(make_box(Vec3(1.0, 0.4, 0.4), Vec3(0.8, 0.0, 0.0)), Vec3(0.0, 0.0, 0.0), 0.5, 7);
}

TEST_CASE("voronoi sites: an impact inside a large solid gets the law of the whole ball and shell", "[voronoi]") {
  // The ball inside the solid and the shell filling it: both drawn whole, as the definition does.
  check_ball_and_shell(make_box(Vec3(4.0, 3.0, 2.0), Vec3(0.5, 0.0, 0.0)), Vec3(0.2, -0.3, 0.1), 0.3, 5);
}
