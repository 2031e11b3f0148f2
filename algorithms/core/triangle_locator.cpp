#include "algorithms/core/triangle_locator.h"

#include <algorithm>
#include <cmath>

namespace shatter {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;  // vertex region a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;  // edge ab
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);  // edge bc
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) return a;  // degenerate triangle: its vertex regions cover it
  return a + ab * (vb / denom) + ac * (vc / denom);  // inside the face
}

Vec3 barycentric_coordinates(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Areas of the sub-triangles against the normal, so that a point off the plane is projected.
  const Vec3 n = (b - a).cross(c - a);
  const double area2 = n.squaredNorm();
  if (!(area2 > 0.0)) return Vec3::Constant(1.0 / 3.0);
  const double wa = (b - p).cross(c - p).dot(n) / area2;
  const double wb = (c - p).cross(a - p).dot(n) / area2;
  return {wa, wb, 1.0 - wa - wb};
}

TriangleLocator::TriangleLocator(const Mesh& mesh, std::span<const std::uint8_t> include) : mesh_(&mesh) {
  const auto binned = [&](std::size_t f) { return include.empty() || include[f] != 0; };
  Aabb box;
  std::size_t count = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!binned(f)) continue;
    ++count;
    for (const std::int32_t v : mesh.triangles[f]) box.extend(mesh.vertices[static_cast<std::size_t>(v)]);
  }
  if (count == 0) return;
  const Vec3 extent = (box.max - box.min).cwiseMax(Vec3::Constant(1e-300));
  // About one triangle per cell, at most 2^21 cells.
  const double cells = std::clamp(static_cast<double>(count), 1.0, 2097152.0);
  cell_ = std::cbrt(extent.prod() / cells);
  if (!(cell_ > 0.0) || !std::isfinite(cell_)) cell_ = extent.maxCoeff();
  cell_ = std::max(cell_, extent.maxCoeff() / 128.0);
  origin_ = box.min;
  for (int i = 0; i < 3; ++i) dims_[i] = std::max(1, static_cast<int>(std::ceil(extent[i] / cell_)));
  const std::size_t total = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  start_.assign(total + 1, 0);
  const auto for_cells = [&](std::size_t f, auto&& visit) {
    Aabb b;
    for (const std::int32_t v : mesh.triangles[f]) b.extend(mesh.vertices[static_cast<std::size_t>(v)]);
    const std::array<int, 3> lo = cell_of(b.min);
    const std::array<int, 3> hi = cell_of(b.max);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          visit((static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x);
  };
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (binned(f)) for_cells(f, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
  triangles_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (binned(f)) for_cells(f, [&](std::size_t c) { triangles_[fill[c]++] = static_cast<std::int32_t>(f); });
}

std::array<int, 3> TriangleLocator::cell_of(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int i = 0; i < 3; ++i) {
    const double x = std::floor((p[i] - origin_[i]) / cell_);
    c[i] = static_cast<int>(std::clamp(std::isfinite(x) ? x : 0.0, 0.0, static_cast<double>(dims_[i] - 1)));
  }
  return c;
}

TriangleLocator::Hit TriangleLocator::nearest(const Vec3& p) const {
  Hit best;
  if (triangles_.empty()) return best;
  const std::array<int, 3> home = cell_of(p);
  const int max_ring = std::max({dims_[0], dims_[1], dims_[2]});
  const auto visit = [&](int x, int y, int z) {
    const std::size_t c = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x;
    for (std::uint32_t i = start_[c]; i < start_[c + 1]; ++i) {
      const std::int32_t f = triangles_[i];
      const Triangle& t = mesh_->triangles[static_cast<std::size_t>(f)];
      const Vec3 q = closest_point_on_triangle(p, mesh_->vertices[static_cast<std::size_t>(t[0])],
                                               mesh_->vertices[static_cast<std::size_t>(t[1])],
                                               mesh_->vertices[static_cast<std::size_t>(t[2])]);
      const double d2 = (q - p).squaredNorm();
      if (d2 < best.distance2 || (d2 == best.distance2 && f < best.triangle)) best = {f, d2};
    }
  };
  for (int r = 0; r <= max_ring; ++r) {
    // The cells at Chebyshev distance r from the home cell.
    for (int z = home[2] - r; z <= home[2] + r; ++z) {
      if (z < 0 || z >= dims_[2]) continue;
      for (int y = home[1] - r; y <= home[1] + r; ++y) {
        if (y < 0 || y >= dims_[1]) continue;
        const bool face = z == home[2] - r || z == home[2] + r || y == home[1] - r || y == home[1] + r;
        for (int x = home[0] - r; x <= home[0] + r; x += (face ? 1 : std::max(1, 2 * r))) {
          if (x < 0 || x >= dims_[0]) continue;
          visit(x, y, z);
        }
      }
    }
    // Every cell beyond ring r is at least r cell widths from the point's projection onto the grid,
    // and so from the point itself.
    if (best.triangle >= 0 && std::sqrt(best.distance2) <= r * cell_) break;
  }
  return best;
}

}  // namespace shatter
