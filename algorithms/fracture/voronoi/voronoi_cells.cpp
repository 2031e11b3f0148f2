#include "algorithms/fracture/voronoi/voronoi_cells.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shatter {

Plane bisector_plane(std::span<const Vec3> sites, int i, int j) {
  const Vec3& a = sites[static_cast<std::size_t>(i)];
  const Vec3& b = sites[static_cast<std::size_t>(j)];
  // a + b is commutative in IEEE arithmetic: both cells get the very same point.
  return Plane{0.5 * (a + b), b - a};
}

std::vector<VoronoiCell> voronoi_cells(std::span<const Vec3> sites, const Aabb& box, double margin) {
  const int n = static_cast<int>(sites.size());
  std::vector<VoronoiCell> cells(sites.size());
  std::vector<std::pair<double, std::int32_t>> order;
  for (int i = 0; i < n; ++i) {
    const Vec3& s = sites[static_cast<std::size_t>(i)];
    order.clear();
    for (int j = 0; j < n; ++j)
      if (j != i) order.emplace_back((sites[static_cast<std::size_t>(j)] - s).squaredNorm(), j);
    std::sort(order.begin(), order.end());
    VoronoiCell& cell = cells[static_cast<std::size_t>(i)];
    cell.polytope = box_polytope(box);
    double r2 = max_corner_distance_squared(cell.polytope, s);
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (order[k].first > 4.0 * r2) break;  // this bisector and all later ones lie beyond the cell
      clip_polytope(cell.polytope, bisector_plane(sites, i, order[k].second), static_cast<int>(k));
      if (!cell.polytope.ok) break;
      r2 = max_corner_distance_squared(cell.polytope, s);
    }
    if (!cell.polytope.ok) r2 = max_corner_distance_squared(box_polytope(box), s);  // the box bounds it
    // Only bisectors within twice the cell's reach can bound it inside the box.
    const double reach = std::sqrt(r2) + margin;
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
