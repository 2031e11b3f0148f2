#pragma once
/// Test solids built by hand, whose volumes and cut areas are known in closed form.

#include "algorithms/core/mesh.h"

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace shatter::test {

/// A prism over a simple counter-clockwise polygon (given with a triangulation), z in [z0, z1].
inline Mesh extrude(const std::vector<Vec2>& polygon, const std::vector<Triangle>& triangulation, double z0,
                    double z1) {
  Mesh m;
  const auto n = static_cast<std::int32_t>(polygon.size());
  for (const Vec2& p : polygon) m.add_vertex({p.x(), p.y(), z0});
  for (const Vec2& p : polygon) m.add_vertex({p.x(), p.y(), z1});
  for (const Triangle& t : triangulation) {
    m.add_triangle(t[0], t[2], t[1], FaceTag::surface);              // bottom, facing -z
    m.add_triangle(t[0] + n, t[1] + n, t[2] + n, FaceTag::surface);  // top, facing +z
  }
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t j = (i + 1) % n;
    m.add_triangle(i, j, j + n, FaceTag::surface);
    m.add_triangle(i, j + n, i + n, FaceTag::surface);
  }
  return m;
}

/// A U-shaped prism: the bar [0,3]x[0,1] and the arms [0,1]x[1,3] and [2,3]x[1,3], z in [0,1]. Volume 7.
inline Mesh make_u_shape() {
  const std::vector<Vec2> u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const std::vector<Triangle> tris = {{0, 1, 4}, {0, 4, 5}, {4, 1, 2}, {4, 2, 3}, {0, 5, 6}, {0, 6, 7}};
  return extrude(u, tris, 0.0, 1.0);
}

/// The unit cube [0,1]^3 with the given diagonal choice on every face (12 triangles).
inline Mesh make_unit_cube() {
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return extrude(square, {{0, 1, 2}, {0, 2, 3}}, 0.0, 1.0);
}

/// Area of a regular n-gon of circumradius r.
inline double regular_polygon_area(int n, double r) {
  return 0.5 * n * r * r * std::sin(2.0 * 3.14159265358979323846 / n);
}

/// The surface of the cube [0, 1]^3, each face a grid of n x n squares (two triangles each), outward:
/// rows of vertices at every k / n, as a game's grid-aligned wall.
inline Mesh grid_cube(int n) {
  Mesh m;
  std::map<std::array<int, 3>, std::int32_t> index;
  const auto vertex = [&](int i, int j, int k) {
    const auto [it, made] = index.try_emplace({i, j, k}, static_cast<std::int32_t>(m.vertices.size()));
    if (made) m.add_vertex(Vec3(double(i) / n, double(j) / n, double(k) / n));
    return it->second;
  };
  // Each face: axis `a` fixed at `side` (0 or n), the other two axes (u, v) spanning it.
  for (int a = 0; a < 3; ++a)
    for (const int side : {0, n}) {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      for (int p = 0; p < n; ++p)
        for (int q = 0; q < n; ++q) {
          std::array<std::int32_t, 4> c{};
          for (int corner = 0; corner < 4; ++corner) {
            std::array<int, 3> at{};
            at[a] = side;
            at[u] = p + (corner == 1 || corner == 2 ? 1 : 0);
            at[v] = q + (corner >= 2 ? 1 : 0);
            c[corner] = vertex(at[0], at[1], at[2]);
          }
          // Outward at side n: (u, v, a) is right-handed; reversed at side 0.
          if (side == n) {
            m.add_triangle(c[0], c[1], c[2], FaceTag::surface);
            m.add_triangle(c[0], c[2], c[3], FaceTag::surface);
          } else {
            m.add_triangle(c[0], c[2], c[1], FaceTag::surface);
            m.add_triangle(c[0], c[3], c[2], FaceTag::surface);
          }
        }
    }
  return m;
}

}  // namespace shatter::test
