#include "algorithms/core/primitives.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace shatter {
namespace {

/// Point on the circle of `radius` around the z axis at step `i` of `n`.
Vec3 ring_point(double radius, int i, int n, double z) {
  const double angle = 2.0 * std::numbers::pi * i / n;
  return {radius * std::cos(angle), radius * std::sin(angle), z};
}

/// Adds the quad (a, b, c, d), counter-clockwise seen from outside, as two triangles.
void add_quad(Mesh& mesh, std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t d) {
  mesh.add_triangle(a, b, c, FaceTag::surface);
  mesh.add_triangle(a, c, d, FaceTag::surface);
}

/// Translates every vertex by `offset`.
void translate(Mesh& mesh, const Vec3& offset) {
  for (Vec3& p : mesh.vertices) p += offset;
}

}  // namespace

Mesh make_box(const Vec3& size, const Vec3& center) {
  assert((size.array() > 0.0).all() && size.allFinite());
  const Vec3 h = 0.5 * size;
  Mesh mesh;
  // Vertex k has the coordinate signs of its bits: bit 0 -> x, bit 1 -> y, bit 2 -> z.
  for (int k = 0; k < 8; ++k)
    mesh.add_vertex(center + Vec3((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z()));
  add_quad(mesh, 0, 2, 3, 1);  // -z
  add_quad(mesh, 4, 5, 7, 6);  // +z
  add_quad(mesh, 0, 1, 5, 4);  // -y
  add_quad(mesh, 2, 6, 7, 3);  // +y
  add_quad(mesh, 0, 4, 6, 2);  // -x
  add_quad(mesh, 1, 3, 7, 5);  // +x
  return mesh;
}

Mesh make_sphere(double radius, int segments, int rings, const Vec3& center) {
  assert(radius > 0.0 && segments >= 3 && rings >= 2);
  segments = std::max(segments, 3);
  rings = std::max(rings, 2);
  Mesh mesh;
  const std::int32_t north = mesh.add_vertex(Vec3(0, 0, radius));
  for (int r = 1; r < rings; ++r) {  // rings of latitude, from the north pole down
    const double polar = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s)
      mesh.add_vertex(ring_point(radius * std::sin(polar), s, segments, radius * std::cos(polar)));
  }
  const std::int32_t south = mesh.add_vertex(Vec3(0, 0, -radius));
  auto at = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    mesh.add_triangle(north, at(1, s), at(1, s + 1), FaceTag::surface);
    for (int r = 1; r + 1 < rings; ++r) add_quad(mesh, at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
    mesh.add_triangle(south, at(rings - 1, s + 1), at(rings - 1, s), FaceTag::surface);
  }
  translate(mesh, center);
  return mesh;
}

Mesh make_cylinder(double radius, double height, int segments, const Vec3& center) {
  assert(radius > 0.0 && height > 0.0 && segments >= 3);
  segments = std::max(segments, 3);
  Mesh mesh;
  const double h = 0.5 * height;
  const std::int32_t bottom = mesh.add_vertex(Vec3(0, 0, -h));
  const std::int32_t top = mesh.add_vertex(Vec3(0, 0, h));
  for (int s = 0; s < segments; ++s) {
    mesh.add_vertex(ring_point(radius, s, segments, -h));
    mesh.add_vertex(ring_point(radius, s, segments, h));
  }
  auto low = [&](int s) { return 2 + 2 * (s % segments); };
  auto high = [&](int s) { return 3 + 2 * (s % segments); };
  for (int s = 0; s < segments; ++s) {
    mesh.add_triangle(bottom, low(s + 1), low(s), FaceTag::surface);
    mesh.add_triangle(top, high(s), high(s + 1), FaceTag::surface);
    add_quad(mesh, low(s), low(s + 1), high(s + 1), high(s));
  }
  translate(mesh, center);
  return mesh;
}

Mesh make_tube(double inner_radius, double outer_radius, double height, int segments, const Vec3& center) {
  assert(inner_radius > 0.0 && inner_radius < outer_radius && height > 0.0 && segments >= 3);
  segments = std::max(segments, 3);
  Mesh mesh;
  const double h = 0.5 * height;
  for (int s = 0; s < segments; ++s) {
    mesh.add_vertex(ring_point(inner_radius, s, segments, -h));
    mesh.add_vertex(ring_point(inner_radius, s, segments, h));
    mesh.add_vertex(ring_point(outer_radius, s, segments, -h));
    mesh.add_vertex(ring_point(outer_radius, s, segments, h));
  }
  // Corner k of column s: 0 inner bottom, 1 inner top, 2 outer bottom, 3 outer top.
  auto v = [&](int s, int k) { return 4 * (s % segments) + k; };
  for (int s = 0; s < segments; ++s) {
    const int n = s + 1;
    add_quad(mesh, v(s, 2), v(n, 2), v(n, 3), v(s, 3));  // outer wall, facing away from the axis
    add_quad(mesh, v(s, 0), v(s, 1), v(n, 1), v(n, 0));  // inner wall, facing the axis
    add_quad(mesh, v(s, 1), v(s, 3), v(n, 3), v(n, 1));  // top annulus, facing +z
    add_quad(mesh, v(s, 0), v(n, 0), v(n, 2), v(s, 2));  // bottom annulus, facing -z
  }
  translate(mesh, center);
  return mesh;
}

Mesh make_torus(double major_radius, double minor_radius, int major_segments, int minor_segments,
                const Vec3& center) {
  assert(minor_radius > 0.0 && major_radius > minor_radius && major_segments >= 3 && minor_segments >= 3);
  major_segments = std::max(major_segments, 3);
  minor_segments = std::max(minor_segments, 3);
  Mesh mesh;
  for (int i = 0; i < major_segments; ++i) {
    for (int j = 0; j < minor_segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / minor_segments;  // around the tube, from outside up
      const double rho = major_radius + minor_radius * std::cos(phi);
      mesh.add_vertex(ring_point(rho, i, major_segments, minor_radius * std::sin(phi)));
    }
  }
  auto v = [&](int i, int j) { return (i % major_segments) * minor_segments + (j % minor_segments); };
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) add_quad(mesh, v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
  translate(mesh, center);
  return mesh;
}

}  // namespace shatter
