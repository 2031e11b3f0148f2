#include "algorithms/fracture/voronoi/point_in_mesh.h"

#include "algorithms/core/predicates.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace shatter {

PointInMesh::PointInMesh(const Mesh& mesh) : mesh_(&mesh), bounds_(bounding_box(mesh)) {
  const double wx = std::max(bounds_.max.x() - bounds_.min.x(), 1e-300);
  const double wy = std::max(bounds_.max.y() - bounds_.min.y(), 1e-300);
  // About two triangles per column on a surface-like mesh, columns as square as the box allows.
  const double columns = std::max(1.0, static_cast<double>(mesh.triangles.size()) / 2.0);
  const double side = std::sqrt(wx * wy / columns);
  nx_ = std::clamp(static_cast<int>(wx / side), 1, 2048);
  ny_ = std::clamp(static_cast<int>(wy / side), 1, 2048);
  cell_x_ = wx / nx_;
  cell_y_ = wy / ny_;
  inverse_x_ = 1.0 / cell_x_;
  inverse_y_ = 1.0 / cell_y_;
  // Two passes (count, fill) over each triangle's column range, found once.
  const std::size_t n = mesh.triangles.size();
  std::vector<std::array<int, 4>> ranges(n);  // x from, y from, x to, y to
  column_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    std::array<int, 4>& r = ranges[f];
    r = {column_x(std::min({a.x(), b.x(), c.x()})), column_y(std::min({a.y(), b.y(), c.y()})),
         column_x(std::max({a.x(), b.x(), c.x()})), column_y(std::max({a.y(), b.y(), c.y()}))};
    for (int iy = r[1]; iy <= r[3]; ++iy)
      for (int ix = r[0]; ix <= r[2]; ++ix) ++column_start_[static_cast<std::size_t>(iy) * nx_ + ix + 1];
  }
  for (std::size_t c = 1; c < column_start_.size(); ++c) column_start_[c] += column_start_[c - 1];
  column_triangles_.resize(static_cast<std::size_t>(column_start_.back()));
  std::vector<std::int32_t> fill(column_start_.begin(), column_start_.end() - 1);
  for (std::size_t f = 0; f < n; ++f) {
    const std::array<int, 4>& r = ranges[f];
    for (int iy = r[1]; iy <= r[3]; ++iy)
      for (int ix = r[0]; ix <= r[2]; ++ix)
        column_triangles_[static_cast<std::size_t>(fill[static_cast<std::size_t>(iy) * nx_ + ix]++)] =
            static_cast<std::int32_t>(f);
  }
}

// Binning and queries use these same two functions, which are monotone in x and y, so a point inside
// a triangle's xy box always falls in one of the triangle's columns.
int PointInMesh::column_x(double x) const {
  return std::clamp(static_cast<int>((x - bounds_.min.x()) * inverse_x_), 0, nx_ - 1);
}

int PointInMesh::column_y(double y) const {
  return std::clamp(static_cast<int>((y - bounds_.min.y()) * inverse_y_), 0, ny_ - 1);
}

int PointInMesh::column(double x, double y) const { return column_y(y) * nx_ + column_x(x); }

InsideAnswer PointInMesh::operator()(const Vec3& q) const {
  if (!bounds_.contains(q)) return InsideAnswer::outside;
  const int col = column(q.x(), q.y());
  const Vec2 p(q.x(), q.y());
  int winding = 0;
  for (std::int32_t k = column_start_[static_cast<std::size_t>(col)];
       k < column_start_[static_cast<std::size_t>(col) + 1]; ++k) {
    const Triangle& t = mesh_->triangles[static_cast<std::size_t>(column_triangles_[static_cast<std::size_t>(k)])];
    const Vec3& a = mesh_->vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh_->vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh_->vertices[static_cast<std::size_t>(t[2])];
    if (p.x() < std::min({a.x(), b.x(), c.x()}) || p.x() > std::max({a.x(), b.x(), c.x()}) ||
        p.y() < std::min({a.y(), b.y(), c.y()}) || p.y() > std::max({a.y(), b.y(), c.y()}))
      continue;
    const Vec2 a2(a.x(), a.y()), b2(b.x(), b.y()), c2(c.x(), c.y());
    const int s0 = orient2d(a2, b2, p);
    const int s1 = orient2d(b2, c2, p);
    const int s2 = orient2d(c2, a2, p);
    const int facing = orient2d(a2, b2, c2);
    if (facing == 0) {
      // A vertical face: its shadow is a segment; a ray along it is degenerate, any other misses it.
      const Vec2* corners[3] = {&a2, &b2, &c2};
      for (int e = 0; e < 3; ++e) {
        const Vec2& u = *corners[e];
        const Vec2& w = *corners[(e + 1) % 3];
        if (orient2d(u, w, p) == 0 && p.x() >= std::min(u.x(), w.x()) && p.x() <= std::max(u.x(), w.x()) &&
            p.y() >= std::min(u.y(), w.y()) && p.y() <= std::max(u.y(), w.y()))
          return InsideAnswer::undecided;
      }
      continue;
    }
    // On a projected edge or vertex: the ray is degenerate.
    if (s0 == 0 || s1 == 0 || s2 == 0) {
      if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return InsideAnswer::undecided;
      continue;
    }
    if (s0 != facing || s1 != facing || s2 != facing) continue;
    const int below = orient3d(a, b, c, q) * facing;  // > 0: q below the face, the ray crosses it
    if (below == 0) return InsideAnswer::undecided;
    if (below > 0) winding += facing;  // leaving through an upward face counts +1
  }
  return winding >= 1 ? InsideAnswer::inside : InsideAnswer::outside;
}

}  // namespace shatter
