// Exact predicates against answers known by construction (points exactly on lines, circles and
// planes, then moved by a few ulps) and against exact integer arithmetic (__int128) on integer inputs.

#include "algorithms/core/predicates.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <array>
#include <random>

using shatter::Vec2;
using shatter::Vec3;

namespace {

using i128 = __int128;

double f(std::int64_t x) { return static_cast<double>(x); }

int sign_of(i128 v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

int orient2d_int(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
                 std::int64_t cy) {
  return sign_of(i128(ax - cx) * (by - cy) - i128(ay - cy) * (bx - cx));
}

int naive_orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double det = (a.x() - c.x()) * (b.y() - c.y()) - (a.y() - c.y()) * (b.x() - c.x());
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

}  // namespace

TEST_CASE("predicates: orient2d on simple triangles", "[predicates]") {
  CHECK(shatter::orient2d({0, 0}, {1, 0}, {0, 1}) == 1);
  CHECK(shatter::orient2d({0, 0}, {0, 1}, {1, 0}) == -1);
  CHECK(shatter::orient2d({0, 0}, {1, 1}, {2, 2}) == 0);
  CHECK(shatter::orient2d({1, 1}, {1, 1}, {3, 7}) == 0);
}

TEST_CASE("predicates: orient2d near a line, ulp grid", "[predicates]") {
  // b and c lie on y = x, so orient2d(p, b, c) = 12 * (p.y - p.x): the sign is known exactly.
  // p.x - c.x needs more than 53 bits, so the differences themselves are inexact in double.
  const Vec2 b(12, 12), c(24, 24);
  const double ulp = std::ldexp(1.0, -53);
  int naive_wrong = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Vec2 p(0.5 + i * ulp, 0.5 + j * ulp);
      const int expected = j > i ? 1 : (j < i ? -1 : 0);
      REQUIRE(shatter::orient2d(p, b, c) == expected);
      REQUIRE(shatter::orient2d(b, c, p) == expected);
      REQUIRE(shatter::orient2d(c, p, b) == expected);
      REQUIRE(shatter::orient2d(b, p, c) == -expected);
      naive_wrong += naive_orient2d(p, b, c) != expected;
    }
  }
  CHECK(naive_wrong > 0);  // the case is hard: plain double evaluation fails on it
}

TEST_CASE("predicates: orient2d matches exact integer arithmetic", "[predicates]") {
  std::mt19937_64 rng(7);
  for (const std::int64_t range : {std::int64_t{4}, std::int64_t{1} << 26}) {
    std::uniform_int_distribution<std::int64_t> coord(-range, range);
    for (int k = 0; k < 20000; ++k) {
      std::int64_t v[6];
      for (auto& x : v) x = coord(rng);
      // Force collinear triples now and then: c = a + t (b - a).
      if (k % 3 == 0 && range < 100) {
        v[4] = v[0] + 2 * (v[2] - v[0]);
        v[5] = v[1] + 2 * (v[3] - v[1]);
      }
      const Vec2 a(f(v[0]), f(v[1])), b(f(v[2]), f(v[3])), c(f(v[4]), f(v[5]));
      REQUIRE(shatter::orient2d(a, b, c) == orient2d_int(v[0], v[1], v[2], v[3], v[4], v[5]));
    }
  }
}

TEST_CASE("predicates: incircle on cocircular points moved by one ulp", "[predicates]") {
  // (5,0), (0,5), (-5,0), (3,4), (4,-3) lie on the circle of radius 5; translated by 2^20 and scaled
  // by 2^-3 (both exact). Moving d towards the centre puts it strictly inside.
  const double t = std::ldexp(1.0, 20);
  const auto at = [&](double x, double y) { return Vec2(t + x / 8, t + y / 8); };
  const Vec2 a = at(5, 0), b = at(0, 5), c = at(-5, 0);
  for (const Vec2& on : {at(3, 4), at(4, -3), at(-3, -4), at(0, -5)}) {
    CHECK(shatter::incircle(a, b, c, on) == 0);
    CHECK(shatter::incircle(b, c, a, on) == 0);
    const Vec2 dir = on - at(0, 0);  // exact: small dyadics
    const Vec2 in(std::nextafter(on.x(), on.x() - dir.x()), std::nextafter(on.y(), on.y() - dir.y()));
    const Vec2 out(std::nextafter(on.x(), on.x() + dir.x()), std::nextafter(on.y(), on.y() + dir.y()));
    CHECK(shatter::incircle(a, b, c, in) == 1);
    CHECK(shatter::incircle(a, b, c, out) == -1);
    CHECK(shatter::incircle(a, c, b, in) == -1);  // clockwise a, b, c flips the sign
  }
  CHECK(shatter::incircle({0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}) == 1);
  CHECK(shatter::incircle({0, 0}, {1, 0}, {0, 1}, {2, 2}) == -1);
}

TEST_CASE("predicates: incircle matches exact integer arithmetic", "[predicates]") {
  std::mt19937_64 rng(11);
  for (const std::int64_t range : {std::int64_t{3}, std::int64_t{1} << 20}) {
    std::uniform_int_distribution<std::int64_t> coord(-range, range);
    for (int k = 0; k < 20000; ++k) {
      std::int64_t v[8];
      for (auto& x : v) x = coord(rng);
      const i128 adx = v[0] - v[6], ady = v[1] - v[7], bdx = v[2] - v[6], bdy = v[3] - v[7];
      const i128 cdx = v[4] - v[6], cdy = v[5] - v[7];
      const i128 det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                       (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                       (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
      const Vec2 a(f(v[0]), f(v[1])), b(f(v[2]), f(v[3]));
      const Vec2 c(f(v[4]), f(v[5])), d(f(v[6]), f(v[7]));
      REQUIRE(shatter::incircle(a, b, c, d) == sign_of(det));
    }
  }
}

TEST_CASE("predicates: incircle on a circle of radius near 2^53", "[predicates]") {
  // Integer points of x^2 + y^2 = N, N a product of 18 primes 1 mod 4 (about 2^106), built as
  // products of Gaussian integers: exactly cocircular, coordinates below 2^53. Moving d by one unit
  // changes the determinant by about R^3 against a permanent of R^4: the filter cannot decide, the
  // later stages must. Truth: d is inside iff |d|^2 < N, times the orientation of a, b, c.
  const std::int64_t gauss[18][2] = {{1, 2}, {2, 3}, {1, 4}, {2, 5}, {1, 6}, {4, 5}, {2, 7}, {5, 6}, {3, 8},
                                     {5, 8}, {4, 9}, {1, 10}, {3, 10}, {7, 8}, {4, 11}, {7, 10}, {6, 11}, {2, 13}};
  i128 norm = 1;
  for (const auto& g : gauss) norm *= g[0] * g[0] + g[1] * g[1];
  std::mt19937_64 rng(19);
  const auto circle_point = [&]() {
    i128 x = 1, y = 0;
    for (const auto& g : gauss) {
      const i128 gy = (rng() & 1) ? g[1] : -g[1];
      const i128 nx = x * g[0] - y * gy, ny = x * gy + y * g[0];
      x = nx;
      y = ny;
    }
    return std::array<std::int64_t, 2>{static_cast<std::int64_t>(x), static_cast<std::int64_t>(y)};
  };
  for (int k = 0; k < 3000; ++k) {
    const auto pa = circle_point(), pb = circle_point(), pc = circle_point(), pd = circle_point();
    if (pa == pb || pb == pc || pa == pc) continue;
    const int turn = orient2d_int(pa[0], pa[1], pb[0], pb[1], pc[0], pc[1]);
    REQUIRE(turn != 0);
    const Vec2 a(f(pa[0]), f(pa[1])), b(f(pb[0]), f(pb[1])), c(f(pc[0]), f(pc[1]));
    REQUIRE(shatter::incircle(a, b, c, Vec2(f(pd[0]), f(pd[1]))) == 0);
    for (const std::int64_t step : {std::int64_t{-1}, std::int64_t{1}}) {
      const std::int64_t dx = pd[0] + step;
      const i128 dist2 = i128(dx) * dx + i128(pd[1]) * pd[1];
      REQUIRE(shatter::incircle(a, b, c, Vec2(f(dx), f(pd[1]))) == turn * sign_of(norm - dist2));
    }
  }
}

TEST_CASE("predicates: orient3d on a plane with coordinates near 2^52", "[predicates]") {
  // Points of x + 2y + 3z = k; d is moved off the plane by one unit in x. Truth: the sign of
  // -(cross_z of (b - a) x (c - a)) * offset, as (b - a) x (c - a) is a multiple of (1, 2, 3).
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 50), std::int64_t{1} << 50);
  const std::int64_t k0 = 12345;
  const auto on_plane = [&]() {
    const std::int64_t y = coord(rng), z = coord(rng);
    return std::array<std::int64_t, 3>{k0 - 2 * y - 3 * z, y, z};
  };
  const auto vec = [](const std::array<std::int64_t, 3>& q) { return Vec3(f(q[0]), f(q[1]), f(q[2])); };
  for (int k = 0; k < 3000; ++k) {
    const auto pa = on_plane(), pb = on_plane(), pc = on_plane(), pd = on_plane();
    const i128 cross_z = i128(pb[0] - pa[0]) * (pc[1] - pa[1]) - i128(pb[1] - pa[1]) * (pc[0] - pa[0]);
    REQUIRE(shatter::orient3d(vec(pa), vec(pb), vec(pc), vec(pd)) == 0);
    for (const std::int64_t offset : {std::int64_t{-1}, std::int64_t{1}}) {
      const Vec3 d(f(pd[0] + offset), f(pd[1]), f(pd[2]));
      REQUIRE(shatter::orient3d(vec(pa), vec(pb), vec(pc), d) == -sign_of(cross_z) * int(offset));
    }
  }
}

TEST_CASE("predicates: orient3d on a tilted plane, ulp offsets", "[predicates]") {
  // Plane z = x/2 + y/4 + 2^30; dyadic points on it are exact doubles.
  const double base = std::ldexp(1.0, 30);
  const auto on = [&](double x, double y) { return Vec3(x, y, x / 2 + y / 4 + base); };
  const Vec3 a = on(0, 0), b = on(64, 0), c = on(0, 64);  // counter-clockwise seen from +z
  for (const Vec3& d : {on(3, 5), on(-1000, 77), on(0.125, 1e6), on(123456, -7)}) {
    CHECK(shatter::orient3d(a, b, c, d) == 0);
    const Vec3 below(d.x(), d.y(), std::nextafter(d.z(), 0.0));
    const Vec3 above(d.x(), d.y(), std::nextafter(d.z(), 1e300));
    CHECK(shatter::orient3d(a, b, c, below) == 1);
    CHECK(shatter::orient3d(a, b, c, above) == -1);
    CHECK(shatter::orient3d(b, a, c, below) == -1);
  }
  CHECK(shatter::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}) == 1);
}

TEST_CASE("predicates: orient3d matches exact integer arithmetic", "[predicates]") {
  std::mt19937_64 rng(13);
  for (const std::int64_t range : {std::int64_t{2}, std::int64_t{1} << 30}) {
    std::uniform_int_distribution<std::int64_t> coord(-range, range);
    for (int k = 0; k < 20000; ++k) {
      std::int64_t v[12];
      for (auto& x : v) x = coord(rng);
      i128 m[3][3];
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) m[r][s] = i128(v[3 * r + s]) - v[9 + s];
      const i128 det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      Vec3 p[4];
      for (int r = 0; r < 4; ++r) p[r] = Vec3(double(v[3 * r]), double(v[3 * r + 1]), double(v[3 * r + 2]));
      REQUIRE(shatter::orient3d(p[0], p[1], p[2], p[3]) == sign_of(det));
    }
  }
}

TEST_CASE("predicates: plane_side on points exactly on the plane", "[predicates]") {
  // normal (3, -5, 0): t = (5 s, 3 s, z) is orthogonal to it, and origin + t is exact for dyadic s.
  const Vec3 origin(0.375, 1e8 + 0.5, -7.25);
  const Vec3 normal(3, -5, 0);
  for (const double s : {0.0, 0.5, -1024.0, 0.001953125, 3.0e5}) {
    const Vec3 p = origin + Vec3(5 * s, 3 * s, 42.0 * s);
    REQUIRE(p.x() - 5 * s == origin.x());  // construction is exact
    REQUIRE(p.y() - 3 * s == origin.y());
    CHECK(shatter::plane_side(p, origin, normal) == 0);
    CHECK(shatter::plane_side(Vec3(std::nextafter(p.x(), 1e300), p.y(), p.z()), origin, normal) == 1);
    CHECK(shatter::plane_side(Vec3(p.x(), std::nextafter(p.y(), 1e300), p.z()), origin, normal) == -1);
  }
  // Normal with components of very different magnitudes; the offset is far below the rounding noise.
  const Vec3 n2(1.0, std::ldexp(1.0, -60), 0.0);
  const Vec3 o2(0.5, 0.0, 0.0);
  CHECK(shatter::plane_side(Vec3(0.5, 0.0, 9.0), o2, n2) == 0);
  CHECK(shatter::plane_side(Vec3(0.5, 0.5, 9.0), o2, n2) == 1);
  // x = 0.5 - 2^-54: dot = -2^-54 + 2^-60 y, zero exactly at y = 64.
  CHECK(shatter::plane_side(Vec3(std::nextafter(0.5, 0.0), std::ldexp(1.0, 5), 0.0), o2, n2) == -1);
  CHECK(shatter::plane_side(Vec3(std::nextafter(0.5, 0.0), std::ldexp(1.0, 6), 0.0), o2, n2) == 0);
  CHECK(shatter::plane_side(Vec3(std::nextafter(0.5, 0.0), std::ldexp(1.0, 8), 0.0), o2, n2) == 1);
}

TEST_CASE("predicates: plane_side matches exact integer arithmetic", "[predicates]") {
  std::mt19937_64 rng(17);
  for (const std::int64_t range : {std::int64_t{3}, std::int64_t{1} << 40}) {
    std::uniform_int_distribution<std::int64_t> coord(-range, range);
    for (int k = 0; k < 20000; ++k) {
      std::int64_t v[9];
      for (auto& x : v) x = coord(rng);
      i128 dot = 0;
      for (int i = 0; i < 3; ++i) dot += i128(v[6 + i]) * (v[i] - v[3 + i]);
      const Vec3 p(f(v[0]), f(v[1]), f(v[2]));
      const Vec3 o(f(v[3]), f(v[4]), f(v[5]));
      const Vec3 n(f(v[6]), f(v[7]), f(v[8]));
      REQUIRE(shatter::plane_side(p, o, n) == sign_of(dot));
    }
  }
}

TEST_CASE("plane_side_snapped: within the snap band on the plane, flagged when not exactly on it", "[predicates]") {
  const Vec3 origin(0.25, 0.0, 0.0);
  const Vec3 normal(1.0, 0.0, 0.0);
  bool snapped = false;
  // Exactly on the plane: 0, not a snap.
  CHECK(shatter::plane_side_snapped(Vec3(0.25, 3.0, -2.0), origin, normal, 1e-14, snapped) == 0);
  CHECK_FALSE(snapped);
  // One ulp off the plane (5.55e-17 at 0.25): 0 with a snap band of 1e-14, flagged; exact without.
  const Vec3 near(std::nextafter(0.25, 1.0), 0.5, 0.5);
  CHECK(shatter::plane_side_snapped(near, origin, normal, 1e-14, snapped) == 0);
  CHECK(snapped);
  snapped = false;
  CHECK(shatter::plane_side_snapped(near, origin, normal, 0.0, snapped) == 1);
  CHECK_FALSE(snapped);
  // Clear of the band: the exact side, whatever the band.
  CHECK(shatter::plane_side_snapped(Vec3(0.25 - 1e-12, 0.0, 0.0), origin, normal, 1e-14, snapped) == -1);
  CHECK(shatter::plane_side_snapped(Vec3(0.25 - 1e-12, 0.0, 0.0), origin, normal, 0.0, snapped) == shatter::plane_side(Vec3(0.25 - 1e-12, 0.0, 0.0), origin, normal));
  // The band is a value of dot(normal, p - origin): a normal of length 4 makes 1e-12 of distance 4e-12.
  snapped = false;
  CHECK(shatter::plane_side_snapped(Vec3(0.25 + 1e-12, 0.0, 0.0), origin, 4.0 * normal, 5e-12, snapped) == 0);
  CHECK(snapped);
}
