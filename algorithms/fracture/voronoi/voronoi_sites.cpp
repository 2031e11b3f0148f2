#include "algorithms/fracture/voronoi/voronoi_sites.h"

#include "algorithms/core/random.h"
#include "algorithms/fracture/voronoi/point_in_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace shatter {
namespace {

/// Accepts a candidate site when it is strictly inside and not a repeat.
class SiteCollector {
 public:
  SiteCollector(const PointInMesh& inside, int wanted) : inside_(inside) {
    sites_.reserve(static_cast<std::size_t>(wanted));
  }
  bool offer(const Vec3& q) {
    if (!q.allFinite() || inside_(q) != InsideAnswer::inside) return false;
    if (std::find(sites_.begin(), sites_.end(), q) != sites_.end()) return false;
    sites_.push_back(q);
    return true;
  }
  [[nodiscard]] const Aabb& bounds() const { return inside_.bounds(); }
  [[nodiscard]] int count() const { return static_cast<int>(sites_.size()); }
  std::vector<Vec3> take() { return std::move(sites_); }

 private:
  const PointInMesh& inside_;
  std::vector<Vec3> sites_;
};

/// Draws of the near distribution (uniform in the ball B(c, r)) that can land in `box`: uniform in the
/// part of the ball's bounding cube inside the box, rejected outside the ball, when that part is
/// smaller than the ball; else uniform in the ball (r cbrt(u) in a uniform direction). Either way a
/// draw that lands in the box is uniform in the ball's part of it, as a draw from the whole ball is.
class NearDraws {
 public:
  NearDraws(const Vec3& c, double r, const Aabb& box) : c_(c), r_(r) {
    lo_ = box.min.cwiseMax(c - Vec3::Constant(r));
    hi_ = box.max.cwiseMin(c + Vec3::Constant(r));
    empty_ = !(lo_.array() <= hi_.array()).all();
    const Vec3 side = (hi_ - lo_).cwiseMax(0.0);
    constexpr double kBall = 4.0 / 3.0 * 3.14159265358979323846;
    in_box_ = !empty_ && side.prod() < kBall * r * r * r;
  }
  /// True when no point of the ball lies in the box: no draw can give a site.
  [[nodiscard]] bool empty() const { return empty_; }
  /// One draw; false when it fell outside the ball (a draw all the same).
  bool next(SplitMix64& rng, Vec3& out) const {
    if (in_box_) {
      out = rng.point_in(lo_, hi_);
      return (out - c_).squaredNorm() <= r_ * r_;
    }
    // Separate statements: the order of two draws inside one expression is unspecified.
    const double distance = r_ * std::cbrt(rng.uniform());
    const Vec3 direction = rng.unit_vector();
    out = c_ + distance * direction;
    return true;
  }

 private:
  Vec3 c_, lo_, hi_;
  double r_;
  bool empty_ = false;
  bool in_box_ = false;
};

/// Draws of the outer distribution (distance d from c uniform in [r, far], direction uniform: a density
/// proportional to 1 / d^2 on that shell) that can land in `box`. When c lies outside the box's bounding
/// sphere (centre m, radius R, at distance L > R from c), the directions are drawn uniformly in the cone
/// of that sphere (half-angle asin(R / L)) and the distances uniformly in [max(r, L - R), min(far,
/// L + R)]: every point of the shell inside the box is in that region, and there the density is the
/// shell's, up to a constant factor, so the points that land in the box follow the same law. Near the
/// box (L <= 2 R), where the cone would be most of the sphere, a point is drawn uniformly in the box
/// and kept with probability (d_lo / d)^2 (d_lo: the least distance from c to the box, at least r), in
/// the shell only: the kept points have the density 1 / d^2 on the box's part of the shell. That is
/// chosen when even its least acceptance, (d_lo / D)^2, is at least the most that a draw from the
/// whole shell can land in the box, V / (4 pi (D - r) d_lo^2) for a box of volume V; otherwise the
/// draws are the shell's own.
class OuterDraws {
 public:
  OuterDraws(const Vec3& c, double r, double far, const Aabb& box) : c_(c), r_(r), far_(far) {
    const Vec3 m = 0.5 * (box.min + box.max);
    // Slightly wide, so that round-off never leaves a corner of the box out of the region.
    const double R = 0.5 * (box.max - box.min).norm() * (1.0 + 1e-9) + 1e-300;
    const double L = (m - c).norm();
    if (!(far > r)) return;
    if (!(L > 2.0 * R)) {
      // The least distance from c to the box, at least r: the densest point of the box's shell part.
      const Vec3 gap = (box.min - c).cwiseMax(c - box.max).cwiseMax(0.0);
      lo_ = std::max(r, gap.norm());
      constexpr double kFourPi = 4.0 * 3.14159265358979323846;
      const double in_box_least = (lo_ / far) * (lo_ / far);
      const double shell_most = (box.max - box.min).prod() / (kFourPi * (far - r) * lo_ * lo_);
      if (in_box_least >= shell_most) {
        mode_ = Mode::box;
        box_ = box;
      }
      return;
    }
    mode_ = Mode::cone;
    axis_ = (m - c) / L;
    const std::array<Vec3, 2> basis = perpendicular_basis(axis_);
    e1_ = basis[0];
    e2_ = basis[1];
    const double sine = R / L;
    cos_max_ = std::sqrt((1.0 - sine) * (1.0 + sine));
    lo_ = std::max(r, (L - R) * (1.0 - 1e-9));
    hi_ = std::min(far, (L + R) * (1.0 + 1e-9));
    empty_ = !(lo_ < hi_);
  }
  /// True when no point of the shell lies in the box: no draw can give a site.
  [[nodiscard]] bool empty() const { return empty_; }
  /// One draw; false when it was not kept (a draw all the same).
  bool next(SplitMix64& rng, Vec3& out) const {
    if (mode_ == Mode::box) {
      out = rng.point_in(box_.min, box_.max);
      const double d2 = (out - c_).squaredNorm();
      const double keep = rng.uniform();
      return d2 >= r_ * r_ && d2 <= far_ * far_ && keep * d2 <= lo_ * lo_;
    }
    if (mode_ == Mode::shell) {
      const double distance = far_ > r_ ? rng.uniform(r_, far_) : r_ * std::cbrt(rng.uniform());
      const Vec3 direction = rng.unit_vector();
      out = c_ + distance * direction;
      return true;
    }
    const double distance = rng.uniform(lo_, hi_);
    // Uniform on the cap: the height along the axis is uniform (Archimedes), the azimuth uniform.
    const double z = 1.0 - rng.uniform() * (1.0 - cos_max_);
    double x = 0.0, y = 0.0, n2 = 0.0;
    do {
      x = rng.uniform(-1.0, 1.0);
      y = rng.uniform(-1.0, 1.0);
      n2 = x * x + y * y;
    } while (!(n2 > 1e-4 && n2 <= 1.0));
    const double ring = std::sqrt(std::max(0.0, (1.0 - z) * (1.0 + z)) / n2);
    out = c_ + distance * (z * axis_ + ring * (x * e1_ + y * e2_));
    return true;
  }

 private:
  /// Two unit vectors perpendicular to the unit `a` and to each other.
  static std::array<Vec3, 2> perpendicular_basis(const Vec3& a) {
    const Vec3 helper = std::abs(a.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 u = a.cross(helper).normalized();
    return {u, a.cross(u)};
  }
  enum class Mode { shell, cone, box };
  Mode mode_ = Mode::shell;
  Vec3 c_, axis_ = Vec3::UnitZ(), e1_ = Vec3::UnitX(), e2_ = Vec3::UnitY();
  Aabb box_;
  double r_, far_, cos_max_ = 1.0, lo_ = 0.0, hi_ = 0.0;
  bool empty_ = false;
};

}  // namespace

Result<std::vector<Vec3>> sample_sites(const Mesh& solid, const FractureParams& params,
                                       const SiteSettings& settings) {
  return sample_sites(PointInMesh(solid), params, settings);
}

Result<std::vector<Vec3>> sample_sites(const PointInMesh& inside, const FractureParams& params,
                                       const SiteSettings& settings) {
  const int wanted = params.fragments;
  SiteCollector sites(inside, wanted);
  SplitMix64 rng(params.seed);
  const Aabb box = sites.bounds();
  const long long budget = static_cast<long long>(settings.max_draws_per_site) * wanted;
  long long draws = 0;

  const bool clustered = params.impact && params.impact->radius > 0.0;
  if (!clustered) {
    while (sites.count() < wanted && draws++ < budget) sites.offer(rng.point_in(box.min, box.max));
  } else {
    const Vec3 c = params.impact->point;
    const double r = params.impact->radius;
    double far = 0.0;  // D: farthest corner of the box from the impact
    for (int k = 0; k < 8; ++k) {
      const Vec3 corner((k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
                        (k & 4) ? box.max.z() : box.min.z());
      far = std::max(far, (corner - c).norm());
    }
    const int near_wanted = far <= r ? wanted : static_cast<int>(std::lround(settings.impact_share * wanted));
    // The ball gets a fair share of the budget; what it cannot hold goes to the outer distribution.
    // Each distribution is drawn only where it can reach the solid's box (NearDraws, OuterDraws): the
    // sites follow the same law as draws from the whole ball and shell, with fewer draws wasted
    // outside a small solid far from the impact (a runtime piece).
    const long long near_budget = static_cast<long long>(settings.max_draws_per_site) * near_wanted / 4;
    const NearDraws near(c, r, box);
    Vec3 q;
    for (long long d = 0; !near.empty() && sites.count() < near_wanted && d < near_budget; ++d, ++draws)
      if (near.next(rng, q)) sites.offer(q);
    const OuterDraws outer(c, r, far, box);
    while (!outer.empty() && sites.count() < wanted && draws++ < budget)
      if (outer.next(rng, q)) sites.offer(q);
  }
  std::vector<Vec3> found = sites.take();
  if (found.empty()) found.push_back(0.5 * (box.min + box.max));
  return found;
}

}  // namespace shatter
