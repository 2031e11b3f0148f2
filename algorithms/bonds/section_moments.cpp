#include "algorithms/bonds/section_moments.h"

#include <cassert>
#include <cmath>

namespace shatter {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

std::vector<Vec2> clip_convex(const std::vector<Vec2>& subject, const std::vector<Vec2>& clip) {
  std::vector<Vec2> out = subject;
  std::vector<Vec2> in;
  const std::size_t n = clip.size();
  for (std::size_t e = 0; e < n && !out.empty(); ++e) {
    const Vec2& p0 = clip[e];
    const Vec2 edge = clip[(e + 1) % n] - p0;
    in.swap(out);
    out.clear();
    // Signed distance (scaled) of a point to the left of the clip edge: >= 0 keeps it.
    auto side = [&](const Vec2& q) { return cross(edge, q - p0); };
    for (std::size_t i = 0; i < in.size(); ++i) {
      const Vec2& cur = in[i];
      const Vec2& nxt = in[(i + 1) % in.size()];
      const double sc = side(cur);
      const double sn = side(nxt);
      if (sc >= 0.0) out.push_back(cur);
      if ((sc >= 0.0) != (sn >= 0.0)) {
        const double t = sc / (sc - sn);  // sc != sn here, and t in [0, 1]
        out.push_back(cur + t * (nxt - cur));
      }
    }
  }
  if (out.size() < 3) out.clear();
  return out;
}

void AreaMoments::add_polygon(const std::vector<Vec2>& polygon) {
  // Green's theorem over the edges (standard polygon moment formulas).
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % n];
    const double c = cross(p, q);
    area += 0.5 * c;
    first_x += c * (p.x() + q.x()) / 6.0;
    first_y += c * (p.y() + q.y()) / 6.0;
    second_xx += c * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) / 12.0;
    second_yy += c * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) / 12.0;
    second_xy += c * (p.x() * q.y() + 2.0 * p.x() * p.y() + 2.0 * q.x() * q.y() + q.x() * p.y()) / 24.0;
  }
}

PrincipalSection principal_section(const AreaMoments& m) {
  assert(m.area > 0.0);
  PrincipalSection s;
  s.centroid = Vec2(m.first_x / m.area, m.first_y / m.area);
  // Central moments: I_x = integral of y^2 (about the x axis), I_y = integral of x^2.
  const double ix = m.second_yy - m.area * s.centroid.y() * s.centroid.y();
  const double iy = m.second_xx - m.area * s.centroid.x() * s.centroid.x();
  const double ixy = m.second_xy - m.area * s.centroid.x() * s.centroid.y();
  // Mohr's circle: the second moment about the axis at angle a is ix cos^2 + iy sin^2 - 2 ixy sin cos.
  const double mean = 0.5 * (ix + iy);
  const double radius = std::hypot(0.5 * (ix - iy), ixy);
  const double angle = 0.5 * std::atan2(-2.0 * ixy, ix - iy);
  s.axis_1 = Vec2(std::cos(angle), std::sin(angle));
  s.axis_2 = Vec2(-s.axis_1.y(), s.axis_1.x());
  s.moment_1 = std::max(mean + radius, 0.0);
  s.moment_2 = std::max(mean - radius, 0.0);
  return s;
}

}  // namespace shatter
