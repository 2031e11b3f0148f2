#include "algorithms/fracture/voronoi/voronoi_sites.h"

#include "algorithms/core/random.h"
#include "algorithms/fracture/voronoi/point_in_mesh.h"

#include <algorithm>
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
    const long long near_budget = static_cast<long long>(settings.max_draws_per_site) * near_wanted / 4;
    // Separate statements: the order of two draws inside one expression is unspecified.
    for (long long d = 0; sites.count() < near_wanted && d < near_budget; ++d, ++draws) {
      const double distance = r * std::cbrt(rng.uniform());
      const Vec3 direction = rng.unit_vector();
      sites.offer(c + distance * direction);
    }
    while (sites.count() < wanted && draws++ < budget) {
      const double distance = far > r ? rng.uniform(r, far) : r * std::cbrt(rng.uniform());
      const Vec3 direction = rng.unit_vector();
      sites.offer(c + distance * direction);
    }
  }
  std::vector<Vec3> found = sites.take();
  if (found.empty()) found.push_back(0.5 * (box.min + box.max));
  return found;
}

}  // namespace shatter
