#include "algorithms/core/convex_hull_volume.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shatter {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

/// True when the points do not all lie in one plane (exact predicates).
bool spans_volume(const std::vector<Point>& p) {
  std::size_t b = 1;
  while (b < p.size() && p[b] == p[0]) ++b;
  std::size_t c = b + 1;
  while (c < p.size() && CGAL::collinear(p[0], p[b], p[c])) ++c;
  if (c >= p.size()) return false;
  for (std::size_t d = c + 1; d < p.size(); ++d)
    if (CGAL::orientation(p[0], p[b], p[c], p[d]) != CGAL::COPLANAR) return true;
  return false;
}

}  // namespace

double convex_hull_volume(std::span<const Vec3> points) {
  if (points.size() < 4) return 0.0;
  std::vector<Point> input;
  input.reserve(points.size());
  for (const Vec3& q : points) input.emplace_back(q.x(), q.y(), q.z());
  if (!spans_volume(input)) return 0.0;
  CGAL::Surface_mesh<Point> hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  // Relative to one input point, so that far-from-origin hulls lose no digits.
  const Vec3 origin = points[0];
  const auto at = [&](CGAL::Surface_mesh<Point>::Vertex_index v) -> Vec3 {
    const Point& q = hull.point(v);
    return Vec3(q.x(), q.y(), q.z()) - origin;
  };
  // CGAL lists the faces in an order that can change from run to run; summed in sorted order, the
  // same faces give the same volume to the last bit.
  std::vector<double> terms;
  terms.reserve(hull.number_of_faces());
  for (const auto f : hull.faces()) {
    auto h = hull.halfedge(f);
    const Vec3 a = at(hull.target(h));
    for (h = hull.next(h); hull.target(hull.next(h)) != hull.target(hull.halfedge(f)); h = hull.next(h))
      terms.push_back(a.dot(at(hull.target(h)).cross(at(hull.target(hull.next(h))))));
  }
  std::sort(terms.begin(), terms.end());
  double six_volume = 0.0;
  for (const double t : terms) six_volume += t;
  const double volume = std::abs(six_volume) / 6.0;
  return std::isfinite(volume) ? volume : 0.0;
}

}  // namespace shatter
