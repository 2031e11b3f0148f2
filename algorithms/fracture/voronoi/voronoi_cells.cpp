#include "algorithms/fracture/voronoi/voronoi_cells.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shatter {
namespace {

using Polygon = std::vector<Vec3>;

/// A convex polytope as its face polygons.
std::vector<Polygon> box_faces(const Aabb& b) {
  const auto corner = [&](int k) {
    return Vec3((k & 1) ? b.max.x() : b.min.x(), (k & 2) ? b.max.y() : b.min.y(),
                (k & 4) ? b.max.z() : b.min.z());
  };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Polygon> faces;
  for (const auto& q : quads) faces.push_back({corner(q[0]), corner(q[1]), corner(q[2]), corner(q[3])});
  return faces;
}

/// Keeps the part of the polytope where dot(normal, x - point) <= 0; the cut face is closed by the
/// crossing points ordered by angle around their mean (the cut of a convex polytope is convex).
void clip(std::vector<Polygon>& faces, const Plane& plane) {
  std::vector<Polygon> kept;
  Polygon cap;
  for (const Polygon& face : faces) {
    Polygon out;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vec3& a = face[k];
      const Vec3& b = face[(k + 1) % face.size()];
      const double da = plane.normal.dot(a - plane.point);
      const double db = plane.normal.dot(b - plane.point);
      if (da <= 0) out.push_back(a);
      if (da == 0) cap.push_back(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
        const Vec3 x = a + (b - a) * (da / (da - db));
        out.push_back(x);
        cap.push_back(x);
      }
    }
    if (out.size() >= 3) kept.push_back(std::move(out));
  }
  if (cap.size() >= 3) {
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : cap) mean += p;
    mean /= static_cast<double>(cap.size());
    const Vec3 u = plane.normal.unitOrthogonal();
    const Vec3 v = plane.normal.normalized().cross(u);
    std::vector<std::pair<double, Vec3>> ordered;
    for (const Vec3& p : cap) ordered.emplace_back(std::atan2((p - mean).dot(v), (p - mean).dot(u)), p);
    std::sort(ordered.begin(), ordered.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    Polygon face;
    for (const auto& o : ordered) face.push_back(o.second);
    kept.push_back(std::move(face));
  }
  faces = std::move(kept);
}

double max_distance_squared(const std::vector<Polygon>& faces, const Vec3& from) {
  double r2 = 0.0;
  for (const Polygon& f : faces)
    for (const Vec3& p : f) r2 = std::max(r2, (p - from).squaredNorm());
  return r2;
}

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
  std::vector<std::pair<double, std::int32_t>> order;
  for (int i = 0; i < n; ++i) {
    const Vec3& s = sites[static_cast<std::size_t>(i)];
    order.clear();
    for (int j = 0; j < n; ++j)
      if (j != i) order.emplace_back((sites[static_cast<std::size_t>(j)] - s).squaredNorm(), j);
    std::sort(order.begin(), order.end());
    VoronoiCell& cell = cells[static_cast<std::size_t>(i)];
    std::vector<Polygon> faces = box_faces(box);
    double r2 = max_distance_squared(faces, s);
    for (const auto& [d2, j] : order) {
      if (d2 > 4.0 * r2) break;  // this bisector and all later ones lie beyond the cell
      clip(faces, bisector_plane(sites, i, j));
      r2 = max_distance_squared(faces, s);
    }
    // Only bisectors within twice the cell's reach can bound it inside the box.
    const double reach = std::sqrt(r2) + margin;
    for (const auto& [d2, j] : order) {
      if (d2 > 4.0 * reach * reach) break;
      cell.neighbours.push_back(j);
    }
    for (const Polygon& f : faces)
      for (const Vec3& p : f) cell.bounds.extend(p);
    cell.bounds.extend(s);
    cell.bounds.min.array() -= margin;
    cell.bounds.max.array() += margin;
  }
  return cells;
}

}  // namespace shatter
