#include "algorithms/fracture/local_fracture.h"

#include "algorithms/core/winding_number.h"
#include "algorithms/fracture/fracture_limits.h"

#include <algorithm>
#include <limits>

namespace shatter {
namespace {

/// Distance from `p` to the box (0 inside).
double distance_to_box(const Aabb& box, const Vec3& p) {
  const Vec3 outside = (box.min - p).cwiseMax(p - box.max).cwiseMax(0.0);
  return outside.norm();
}

/// Distance from `p` to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

double distance_to_surface(const Mesh& mesh, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles)
    best = std::min(best, distance_to_triangle(p, mesh.vertices[static_cast<std::size_t>(t[0])],
                                               mesh.vertices[static_cast<std::size_t>(t[1])],
                                               mesh.vertices[static_cast<std::size_t>(t[2])]));
  return best;
}

bool contains(const Mesh& mesh, const Vec3& p) { return winding_number(mesh, p) > 0.5; }

}  // namespace

std::vector<int> fragments_near_impact(std::span<const Fragment> fragments, const Impact& impact) {
  return fragments_near_impact(fragments, impact, NearImpactOptions{});
}

std::vector<int> fragments_near_impact(std::span<const Fragment> fragments, const Impact& impact,
                                       const NearImpactOptions& options) {
  const auto eligible = [&](std::size_t i) { return options.eligible.empty() || options.eligible[i] != 0; };
  const bool cull = options.cull_by_box;
  std::vector<int> hit;
  const Vec3& p = impact.point;
  if (impact.radius > 0) {
    for (std::size_t i = 0; i < fragments.size(); ++i) {
      if (!eligible(i)) continue;
      const Mesh& m = fragments[i].mesh;
      if (cull && distance_to_box(bounding_box(m), p) > impact.radius) continue;
      if (distance_to_surface(m, p) <= impact.radius || contains(m, p)) hit.push_back(static_cast<int>(i));
    }
    return hit;
  }
  // Radius 0: the fragment holding the point, else the nearest surface.
  int nearest = -1;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    if (!eligible(i)) continue;
    const Mesh& m = fragments[i].mesh;
    const Aabb box = bounding_box(m);
    if ((!cull || box.contains(p)) && contains(m, p)) return {static_cast<int>(i)};
    if (cull && distance_to_box(box, p) >= nearest_distance) continue;
    const double d = distance_to_surface(m, p);
    if (d < nearest_distance) {
      nearest_distance = d;
      nearest = static_cast<int>(i);
    }
  }
  if (nearest >= 0) hit.push_back(nearest);
  return hit;
}

Result<LocalFracture> fracture_near_impact(const Fracturer& fracturer, std::span<const Fragment> fragments,
                                           const Impact& impact, const FractureParams& params) {
  FractureParams local = params;
  local.impact = impact;
  // The fragments themselves are checked by the fracturer, one fragment at a time.
  if (Status s = check_fracture_request(local, fracturer.name()); !s) return s.error();
  LocalFracture out;
  out.hit = fragments_near_impact(fragments, impact);
  for (const int i : out.hit) {
    Result<std::vector<Fragment>> pieces = fracturer.fracture(fragments[static_cast<std::size_t>(i)].mesh, local);
    if (!pieces) return pieces.error();
    out.pieces.push_back(std::move(*pieces));
  }
  return out;
}

}  // namespace shatter
