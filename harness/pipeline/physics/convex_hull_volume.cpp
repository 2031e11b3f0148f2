#include "harness/pipeline/physics/convex_hull_volume.h"

#include <LinearMath/btConvexHullComputer.h>

#include <cmath>

namespace shatter {

double convex_hull_volume(std::span<const Vec3> points) {
  if (points.size() < 4) return 0.0;
  // Vec3 is three contiguous doubles (Eigen, no padding): stride sizeof(Vec3).
  btConvexHullComputer hull;
  hull.compute(points.data()->data(), static_cast<int>(sizeof(Vec3)), static_cast<int>(points.size()), 0, 0);
  if (hull.faces.size() < 4) return 0.0;
  const auto point = [&](int hull_vertex) -> const Vec3& {
    return points[static_cast<std::size_t>(hull.original_vertex_index[hull_vertex])];
  };
  // Relative to one hull vertex, so that far-from-origin hulls lose no digits.
  const Vec3 origin = point(0);
  double six_volume = 0.0;
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const Vec3 a = point(first->getSourceVertex()) - origin;
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace(); e->getTargetVertex() != first->getSourceVertex();
         e = e->getNextEdgeOfFace()) {
      const Vec3 b = point(e->getSourceVertex()) - origin;
      const Vec3 c = point(e->getTargetVertex()) - origin;
      six_volume += a.dot(b.cross(c));
    }
  }
  const double volume = std::abs(six_volume) / 6.0;
  return std::isfinite(volume) ? volume : 0.0;
}

}  // namespace shatter
