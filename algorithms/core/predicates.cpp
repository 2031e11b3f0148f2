/// Exact predicates: a static-filter evaluation in double precision, and, when its forward error bound
/// cannot decide the sign, an exact evaluation in floating-point expansion arithmetic.
///
/// Design note. An expansion is a sum of doubles that are nonoverlapping and sorted by increasing
/// magnitude, with zeros removed; its sign is the sign of its last (largest) component. The only
/// operation that builds one is `Expansion::add` (growing by one double, error-free by TwoSum), so an
/// expansion stays valid whatever doubles are added to it, in any order. Differences of input
/// coordinates become two-term expansions and every product of components is split error-free by
/// TwoProduct (std::fma), so the exact sign follows from the given doubles with no rounding anywhere.
///
/// Assumptions: IEEE-754 binary64 arithmetic rounding to nearest (no x87 excess precision, no
/// -ffast-math). Exactness holds when no product overflows or underflows: every non-zero coordinate
/// and normal component, and every non-zero difference of coordinates, has a magnitude in
/// [2^-180, 2^180] (incircle is of degree 4 in the differences). Inputs must be finite.
///
/// Filter bounds: with k roundings on the longest path through the expression, the computed value
/// differs from the exact one by at most k*eps*P + O(eps^2)*P, where P is the computed permanent
/// (the expression with every term replaced by its absolute value) and eps = 2^-53. The final
/// rounding never changes a sign, so it is not counted. The constants below use (k + 1)*eps: the
/// extra eps*P covers the second-order terms and the rounding of the bound itself with a wide margin.
///
/// Middle stage (incircle, orient3d): nearly cocircular or coplanar inputs from rounded geometry
/// (regular polygons, cylinder cuts) fail the filter often, but only by the rounding noise of the
/// inputs, far above eps^2 * P. Those are evaluated in double-double arithmetic from the exact
/// two-term differences: a double-double add errs by at most 5 eps^2 (|x| + |y|), a multiply by
/// 9 eps^2 |x| |y|; along incircle's longest chain (lift 14, minor 14, product 9, two sums 5 + 5) the
/// total is below 47 eps^2 P, and orient3d's below 42 eps^2 P. The bound used is 64 eps^2 P.

#include "algorithms/core/predicates.h"

#include <cassert>
#include <cmath>

namespace shatter {
namespace {

constexpr double kEps = 0x1p-53;
constexpr double kPlaneBound = 4.0 * kEps;     // 1 difference + 1 product + 1 non-final sum
constexpr double kOrient2dBound = 4.0 * kEps;  // 2 differences + 1 product
constexpr double kOrient3dBound = 8.0 * kEps;  // 3 differences + 2 products + 1 minor + 1 sum
constexpr double kIncircleBound = 11.0 * kEps; // 2 diffs + 1 mul + 1 lift sum, 4 minor, 1 mul, 1 sum

/// x + y == a + b exactly, |y| <= ulp(x)/2 (Knuth's branch-free TwoSum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

/// x + y == a * b exactly (no underflow assumed).
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

constexpr double kDoubleDoubleBound = 64.0 * kEps * kEps;

/// hi + lo with |lo| <= eps |hi|.
struct DoubleDouble {
  double hi;
  double lo;
};

inline DoubleDouble dd_difference(double a, double b) {
  DoubleDouble r;
  two_sum(a, -b, r.hi, r.lo);
  return r;
}

inline DoubleDouble dd_add(const DoubleDouble& x, const DoubleDouble& y) {
  double s;
  double e;
  two_sum(x.hi, y.hi, s, e);
  e += x.lo + y.lo;
  DoubleDouble r;
  two_sum(s, e, r.hi, r.lo);
  return r;
}

inline DoubleDouble dd_neg(const DoubleDouble& x) { return {-x.hi, -x.lo}; }

inline DoubleDouble dd_mul(const DoubleDouble& x, const DoubleDouble& y) {
  double p;
  double e;
  two_product(x.hi, y.hi, p, e);
  e += x.hi * y.lo + x.lo * y.hi;
  DoubleDouble r;
  two_sum(p, e, r.hi, r.lo);
  return r;
}

/// Sign of a double-double value with absolute error at most `bound`, or 0 when undecided.
inline int dd_sign(const DoubleDouble& x, double bound) {
  // |hi + lo| >= |hi| (1 - 2 eps); the 4 eps also absorbs the rounding of the product.
  if (std::abs(x.hi) * (1.0 - 4.0 * kEps) > bound) return x.hi > 0.0 ? 1 : -1;
  return 0;
}

/// A nonoverlapping expansion of at most N components, increasing magnitude, no zero components.
template <int N>
struct Expansion {
  int size = 0;
  double c[N];

  /// Adds `b` exactly (Shewchuk's GROW-EXPANSION with zero elimination, in place).
  void add(double b) {
    double q = b;
    int m = 0;
    for (int i = 0; i < size; ++i) {
      double s;
      double e;
      two_sum(q, c[i], s, e);
      if (e != 0.0) c[m++] = e;  // m <= i: never overwrites an unread component
      q = s;
    }
    if (q != 0.0) {
      assert(m < N);
      c[m++] = q;
    }
    size = m;
  }

  /// Sign of the exact sum.
  [[nodiscard]] int sign() const { return size == 0 ? 0 : (c[size - 1] > 0.0 ? 1 : -1); }
};

/// a - b as an exact expansion of at most two components.
inline Expansion<2> difference(double a, double b) {
  Expansion<2> e;
  e.add(a);
  e.add(-b);
  return e;
}

/// out += s * (a * b) exactly, s = +1 or -1.
template <int N, int A, int B>
inline void add_product(Expansion<N>& out, const Expansion<A>& a, const Expansion<B>& b, double s) {
  for (int i = 0; i < a.size; ++i) {
    for (int j = 0; j < b.size; ++j) {
      double x;
      double y;
      two_product(a.c[i], b.c[j], x, y);
      out.add(s * y);
      out.add(s * x);
    }
  }
}

/// out += s * (a * b) exactly for a double b.
template <int N, int A>
inline void add_scaled(Expansion<N>& out, const Expansion<A>& a, double b, double s) {
  for (int i = 0; i < a.size; ++i) {
    double x;
    double y;
    two_product(a.c[i], b, x, y);
    out.add(s * y);
    out.add(s * x);
  }
}

/// m = x1*y2 - x2*y1 exactly, with each factor a two-component expansion.
inline Expansion<16> cross(const Expansion<2>& x1, const Expansion<2>& y2, const Expansion<2>& x2,
                           const Expansion<2>& y1) {
  Expansion<16> m;
  add_product(m, x1, y2, 1.0);
  add_product(m, x2, y1, -1.0);
  return m;
}

[[gnu::noinline]] int plane_side_slow(const Vec3& p, const Vec3& origin, const Vec3& normal) {
  Expansion<12> sum;
  for (int i = 0; i < 3; ++i) add_scaled(sum, difference(p[i], origin[i]), normal[i], 1.0);
  return sum.sign();
}

[[gnu::noinline]] int orient2d_slow(const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(difference(a.x(), c.x()), difference(b.y(), c.y()), difference(a.y(), c.y()),
               difference(b.x(), c.x()))
      .sign();
}

[[gnu::noinline]] int orient3d_slow(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                     double permanent) {
  // Four points with one coordinate equal lie in an axis plane: exactly coplanar. Faces of boxes and
  // of axis-aligned walls meet this often, and the stages below could only prove the zero the slow way.
  for (int i = 0; i < 3; ++i)
    if (a[i] == d[i] && b[i] == d[i] && c[i] == d[i]) return 0;
  {
    DoubleDouble ad[3];
    DoubleDouble bd[3];
    DoubleDouble cd[3];
    for (int i = 0; i < 3; ++i) {
      ad[i] = dd_difference(a[i], d[i]);
      bd[i] = dd_difference(b[i], d[i]);
      cd[i] = dd_difference(c[i], d[i]);
    }
    const auto minor = [](const DoubleDouble& x1, const DoubleDouble& y2, const DoubleDouble& x2,
                          const DoubleDouble& y1) { return dd_add(dd_mul(x1, y2), dd_neg(dd_mul(x2, y1))); };
    const DoubleDouble det = dd_add(dd_add(dd_mul(ad[2], minor(bd[0], cd[1], cd[0], bd[1])),
                                           dd_mul(bd[2], minor(cd[0], ad[1], ad[0], cd[1]))),
                                    dd_mul(cd[2], minor(ad[0], bd[1], bd[0], ad[1])));
    const int sign = dd_sign(det, kDoubleDoubleBound * permanent);
    if (sign != 0) return sign;
  }
  Expansion<2> ad[3];
  Expansion<2> bd[3];
  Expansion<2> cd[3];
  for (int i = 0; i < 3; ++i) {
    ad[i] = difference(a[i], d[i]);
    bd[i] = difference(b[i], d[i]);
    cd[i] = difference(c[i], d[i]);
  }
  // det = adz*(bdx*cdy - cdx*bdy) + bdz*(cdx*ady - adx*cdy) + cdz*(adx*bdy - bdx*ady)
  Expansion<192> det;
  add_product(det, ad[2], cross(bd[0], cd[1], cd[0], bd[1]), 1.0);
  add_product(det, bd[2], cross(cd[0], ad[1], ad[0], cd[1]), 1.0);
  add_product(det, cd[2], cross(ad[0], bd[1], bd[0], ad[1]), 1.0);
  return det.sign();
}

[[gnu::noinline]] int incircle_slow(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                                     double permanent) {
  {
    const DoubleDouble adx = dd_difference(a.x(), d.x()), ady = dd_difference(a.y(), d.y());
    const DoubleDouble bdx = dd_difference(b.x(), d.x()), bdy = dd_difference(b.y(), d.y());
    const DoubleDouble cdx = dd_difference(c.x(), d.x()), cdy = dd_difference(c.y(), d.y());
    const auto lift = [](const DoubleDouble& x, const DoubleDouble& y) { return dd_add(dd_mul(x, x), dd_mul(y, y)); };
    const auto minor = [](const DoubleDouble& x1, const DoubleDouble& y2, const DoubleDouble& x2,
                          const DoubleDouble& y1) { return dd_add(dd_mul(x1, y2), dd_neg(dd_mul(x2, y1))); };
    const DoubleDouble det = dd_add(dd_add(dd_mul(lift(adx, ady), minor(bdx, cdy, cdx, bdy)),
                                           dd_mul(lift(bdx, bdy), minor(cdx, ady, adx, cdy))),
                                    dd_mul(lift(cdx, cdy), minor(adx, bdy, bdx, ady)));
    const int sign = dd_sign(det, kDoubleDoubleBound * permanent);
    if (sign != 0) return sign;
  }
  const Expansion<2> adx = difference(a.x(), d.x());
  const Expansion<2> ady = difference(a.y(), d.y());
  const Expansion<2> bdx = difference(b.x(), d.x());
  const Expansion<2> bdy = difference(b.y(), d.y());
  const Expansion<2> cdx = difference(c.x(), d.x());
  const Expansion<2> cdy = difference(c.y(), d.y());
  auto lift = [](const Expansion<2>& x, const Expansion<2>& y) {
    Expansion<16> l;
    add_product(l, x, x, 1.0);
    add_product(l, y, y, 1.0);
    return l;
  };
  // det = alift*(bdx*cdy - cdx*bdy) + blift*(cdx*ady - adx*cdy) + clift*(adx*bdy - bdx*ady)
  Expansion<1536> det;
  add_product(det, lift(adx, ady), cross(bdx, cdy, cdx, bdy), 1.0);
  add_product(det, lift(bdx, bdy), cross(cdx, ady, adx, cdy), 1.0);
  add_product(det, lift(cdx, cdy), cross(adx, bdy, bdx, ady), 1.0);
  return det.sign();
}

}  // namespace

namespace {

/// dot(normal, p - origin) rounded, and the bound on its error beyond which its sign is exact.
struct RoundedPlaneDot {
  double det;
  double bound;
};

RoundedPlaneDot rounded_plane_dot(const Vec3& p, const Vec3& origin, const Vec3& normal) {
  const double tx = normal.x() * (p.x() - origin.x());
  const double ty = normal.y() * (p.y() - origin.y());
  const double tz = normal.z() * (p.z() - origin.z());
  return {tx + ty + tz, kPlaneBound * (std::abs(tx) + std::abs(ty) + std::abs(tz))};
}

}  // namespace

int plane_side(const Vec3& p, const Vec3& origin, const Vec3& normal) {
  const RoundedPlaneDot d = rounded_plane_dot(p, origin, normal);
  if (d.det > d.bound) return 1;
  if (-d.det > d.bound) return -1;
  return plane_side_slow(p, origin, normal);
}

int plane_side_snapped(const Vec3& p, const Vec3& origin, const Vec3& normal, double snap_dot, bool& snapped) {
  const RoundedPlaneDot d = rounded_plane_dot(p, origin, normal);
  if (std::abs(d.det) <= snap_dot) {
    snapped = plane_side_slow(p, origin, normal) != 0;
    return 0;
  }
  if (d.det > d.bound) return 1;
  if (-d.det > d.bound) return -1;
  return plane_side_slow(p, origin, normal);
}

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  const double bound = kOrient2dBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return orient2d_slow(a, b, c);
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y(), adz = a.z() - d.z();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y(), bdz = b.z() - d.z();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y(), cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  const double bound = kOrient3dBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return orient3d_slow(a, b, c, d, permanent);
}

int incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * alift +
                           (std::abs(cdxady) + std::abs(adxcdy)) * blift +
                           (std::abs(adxbdy) + std::abs(bdxady)) * clift;
  const double bound = kIncircleBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return incircle_slow(a, b, c, d, permanent);
}

}  // namespace shatter
