#include "algorithms/core/polygon_triangulation.h"

#include "algorithms/core/cap_triangulator.h"
#include "algorithms/core/predicates.h"
#include "algorithms/core/representable_range.h"

#include <cmath>
#include <string>

namespace shatter {
namespace {

void fan(std::span<const std::int32_t> poly, std::vector<Triangle>& out) {
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) out.push_back({poly[0], poly[i], poly[i + 1]});
}

}  // namespace

Status triangulate_polygon(const std::vector<Vec3>& vertices, std::span<const std::int32_t> poly,
                           std::vector<Triangle>& out) {
  const std::size_t m = poly.size();
  if (m == 3) {
    out.push_back({poly[0], poly[1], poly[2]});
    return {};
  }
  // The exact predicates are exact only while their products neither overflow nor underflow: a
  // corner beyond the representable range (which every solid must keep anyway) is refused here,
  // before the triangulation could walk on inconsistent orientations.
  for (const std::int32_t corner : poly)
    if (!within_coordinate_range(vertices[corner]))
      return Error{"a corner lies outside the representable range (every |coordinate| <= " +
                   std::to_string(static_cast<long long>(kMaxCoordinate)) + " m)"};
  const Vec3& origin = vertices[poly[0]];
  Vec3 normal = Vec3::Zero();  // Newell: twice the vector area
  for (std::size_t i = 0; i < m; ++i)
    normal += (vertices[poly[i]] - origin).cross(vertices[poly[(i + 1) % m]] - origin);
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  if (normal[axis] == 0.0 || !std::isfinite(normal[axis])) {
    fan(poly, out);
    return {};
  }
  // Project by dropping the dominant axis, keeping the cyclic order so that a corner turning like
  // the polygon has the sign of normal[axis].
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const int sign = normal[axis] > 0.0 ? 1 : -1;
  std::vector<Vec2> pts(m);
  for (std::size_t i = 0; i < m; ++i) pts[i] = Vec2(vertices[poly[i]][u], vertices[poly[i]][w]);

  if (m == 4) {  // four strictly convex corners can only make a convex quad (its turns sum to 360 degrees)
    bool convex = true;
    for (std::size_t i = 0; convex && i < m; ++i) convex = sign * orient2d(pts[(i + m - 1) % m], pts[i], pts[(i + 1) % m]) > 0;
    if (convex) {
      fan(poly, out);
      return {};
    }
  }
  // The constrained triangulation wants the inside on the left of its edges: a clockwise projection
  // is walked backwards and its triangles turned back afterwards.
  std::vector<CapEdge> edges(m);
  for (std::size_t i = 0; i < m; ++i) {
    const auto a = static_cast<std::int32_t>(i), b = static_cast<std::int32_t>((i + 1) % m);
    edges[i] = sign > 0 ? CapEdge{a, b} : CapEdge{b, a};
  }
  const CapTriangulation cdt = triangulate_cap(pts, edges, InsertionOrder::randomized_rounds);
  if (!cdt.ok) return Error{"polygon crosses itself (" + cdt.error + ")"};
  if (cdt.triangles.empty()) {
    fan(poly, out);
    return {};
  }
  for (const Triangle& t : cdt.triangles) {
    if (sign > 0)
      out.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
    else
      out.push_back({poly[t[0]], poly[t[2]], poly[t[1]]});
  }
  return {};
}

}  // namespace shatter
