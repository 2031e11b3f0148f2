#include "algorithms/fracture/voronoi/voronoi_cells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace shatter {
namespace {

/// A uniform grid over the sites, about one site per bucket, that lists the sites nearest to a site
/// in the order of a full sort without looking at the others: every site within distance R of the
/// query lies in the buckets that cover the cube of half-side R around it.
class SiteGrid {
 public:
  explicit SiteGrid(std::span<const Vec3> sites) : sites_(sites) {
    lo_ = hi_ = sites.empty() ? Vec3::Zero() : sites[0];
    for (const Vec3& s : sites) {
      lo_ = lo_.cwiseMin(s);
      hi_ = hi_.cwiseMax(s);
    }
    const Vec3 extent = hi_ - lo_;
    const double largest = extent.maxCoeff();
    // Flat or linear site sets get thin slabs rather than a zero-width axis.
    const Vec3 sides = extent.cwiseMax(largest * 1e-3).cwiseMax(1e-300);
    const double n = static_cast<double>(std::max<std::size_t>(sites.size(), 1));
    bucket_ = std::cbrt(sides.x() / n * sides.y() * sides.z());
    if (!(bucket_ > 0.0) || !std::isfinite(bucket_)) bucket_ = std::max(largest, 1e-300);
    for (int a = 0; a < 3; ++a)
      dims_[a] = static_cast<int>(std::clamp(std::ceil(sides[a] / bucket_), 1.0, 4096.0));
    start_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    std::vector<std::int64_t> bucket_of(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) {
      bucket_of[i] = flat(cell(sites[i]));
      ++start_[static_cast<std::size_t>(bucket_of[i]) + 1];
    }
    for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
    members_.resize(sites.size());
    std::vector<std::int32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < sites.size(); ++i)
      members_[static_cast<std::size_t>(fill[static_cast<std::size_t>(bucket_of[i])]++)] = static_cast<std::int32_t>(i);
  }

  /// Bucket edge length, m.
  [[nodiscard]] double bucket() const { return bucket_; }

  /// The sites other than `i` within distance `radius` of it, as (squared distance, index) sorted;
  /// `all` says whether the buckets searched covered the whole grid (then every other site is listed).
  void near(int i, double radius, std::vector<std::pair<double, std::int32_t>>& out, bool& all) const {
    const Vec3& s = sites_[static_cast<std::size_t>(i)];
    const std::array<int, 3> a = cell(s - Vec3::Constant(radius)), b = cell(s + Vec3::Constant(radius));
    all = a == std::array<int, 3>{0, 0, 0} && b == std::array<int, 3>{dims_[0] - 1, dims_[1] - 1, dims_[2] - 1};
    const double r2 = radius * radius;
    out.clear();
    for (int z = a[2]; z <= b[2]; ++z)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int x = a[0]; x <= b[0]; ++x) {
          const std::int64_t f = flat({x, y, z});
          for (std::int32_t k = start_[static_cast<std::size_t>(f)]; k < start_[static_cast<std::size_t>(f) + 1]; ++k) {
            const std::int32_t j = members_[static_cast<std::size_t>(k)];
            if (j == i) continue;
            const double d2 = (sites_[static_cast<std::size_t>(j)] - s).squaredNorm();
            if (all || d2 <= r2) out.emplace_back(d2, j);
          }
        }
    std::sort(out.begin(), out.end());
  }

 private:
  [[nodiscard]] std::array<int, 3> cell(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) {
      const double t = std::floor((p[a] - lo_[a]) / bucket_);  // clamped in double: no overflowing conversion
      c[static_cast<std::size_t>(a)] = static_cast<int>(std::clamp(t, 0.0, static_cast<double>(dims_[a] - 1)));
    }
    return c;
  }
  [[nodiscard]] std::int64_t flat(const std::array<int, 3>& c) const {
    return (static_cast<std::int64_t>(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
  }

  std::span<const Vec3> sites_;
  Vec3 lo_, hi_;
  double bucket_ = 1.0;
  int dims_[3] = {1, 1, 1};
  std::vector<std::int32_t> start_;    // bucket b holds members_[start_[b] .. start_[b + 1])
  std::vector<std::int32_t> members_;
};

}  // namespace

Plane bisector_plane(std::span<const Vec3> sites, int i, int j) {
  const Vec3& a = sites[static_cast<std::size_t>(i)];
  const Vec3& b = sites[static_cast<std::size_t>(j)];
  // a + b is commutative in IEEE arithmetic: both cells get the very same point.
  return Plane{0.5 * (a + b), b - a};
}

std::vector<VoronoiCell> voronoi_cells(std::span<const Vec3> sites, const Aabb& box, double margin) {
  const int n = static_cast<int>(sites.size());
  std::vector<VoronoiCell> cells(sites.size());
  const SiteGrid grid(sites);
  // `order` is the prefix of the other sites sorted by (squared distance, index) that is complete up
  // to `radius`: the same prefix a full sort gives, so the cells do not depend on the grid.
  std::vector<std::pair<double, std::int32_t>> order;
  for (int i = 0; i < n; ++i) {
    const Vec3& s = sites[static_cast<std::size_t>(i)];
    double radius = 2.0 * grid.bucket();
    bool all = false;
    grid.near(i, radius, order, all);
    // Widens the search until it holds every site within `needed` (or every site).
    const auto cover = [&](double needed) {
      while (!all && radius < needed) {
        radius = std::max(2.0 * radius, needed);
        grid.near(i, radius, order, all);
      }
    };
    VoronoiCell& cell = cells[static_cast<std::size_t>(i)];
    cell.polytope = box_polytope(box);
    double r2 = max_corner_distance_squared(cell.polytope, s);
    for (std::size_t k = 0;; ++k) {
      if (k == order.size()) {
        cover(2.0 * std::sqrt(r2));  // the sites past the prefix may still bound the cell
        if (k == order.size()) break;
      }
      if (order[k].first > 4.0 * r2) break;  // this bisector and all later ones lie beyond the cell
      const std::size_t corners_before = cell.polytope.corners.size();
      clip_polytope(cell.polytope, bisector_plane(sites, i, order[k].second), static_cast<int>(k));
      if (!cell.polytope.ok) break;
      // A plane that cuts makes corners; one that misses leaves the cell, and its reach, as they were.
      if (cell.polytope.corners.size() != corners_before) r2 = max_corner_distance_squared(cell.polytope, s);
    }
    if (!cell.polytope.ok) r2 = max_corner_distance_squared(box_polytope(box), s);  // the box bounds it
    // Only bisectors within twice the cell's reach can bound it inside the box.
    const double reach = std::sqrt(r2) + margin;
    cover(2.0 * reach);
    for (const auto& [d2, j] : order) {
      if (d2 > 4.0 * reach * reach) break;
      cell.neighbours.push_back(j);
    }
    if (cell.polytope.ok) {
      for (const CellPolytope::Face& f : cell.polytope.faces)
        for (const std::int32_t c : f.corners) cell.bounds.extend(cell.polytope.corners[static_cast<std::size_t>(c)]);
    } else {
      cell.bounds = box;
    }
    cell.bounds.extend(s);
    cell.bounds.min.array() -= margin;
    cell.bounds.max.array() += margin;
  }
  return cells;
}

}  // namespace shatter
