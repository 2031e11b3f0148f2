#include "algorithms/core/mass_properties.h"

#include <Eigen/Geometry>

#include <array>
#include <cassert>

namespace shatter {
namespace {

/// A point near the mesh (the centre of its bounding box): the integrals are taken relative to it so
/// that a mesh far from the origin keeps its digits.
Vec3 reference_point(const Mesh& mesh) {
  if (mesh.vertices.empty()) return Vec3::Zero();
  const Aabb box = bounding_box(mesh);
  const Vec3 centre = 0.5 * (box.min + box.max);
  return centre.allFinite() ? centre : Vec3::Zero();
}

}  // namespace

// Each outward triangle (a, b, c), taken relative to the reference point, spans a signed tetrahedron
// with it, of determinant D = a . (b x c) and volume D / 6. Mapping the unit tetrahedron onto it
// (x = a u + b v + c w), the moments over the unit tetrahedron are int 1 = 1/6, int u = 1/24,
// int u^2 = 1/60 and int u v = 1/120, so
//   first moment   int x dV     = D / 24 (a + b + c),
//   second moment  int x x^T dV = D / 120 (a a^T + b b^T + c c^T + s s^T),  s = a + b + c
// (the diagonal terms give D (2/120) a a^T = D/60 a a^T, the mixed ones D/120 (a b^T + b a^T)).
// By the divergence theorem the sums over a closed surface are the integrals over the solid.
MassProperties mass_properties(const Mesh& mesh) {
  assert(mesh.tags.size() == mesh.triangles.size());
  const Vec3 origin = reference_point(mesh);
  double six_volume = 0.0;
  Vec3 moment24 = Vec3::Zero();  // 24 * first moment
  // 120 * second moment, symmetric: its six distinct entries (xx, yy, zz, xy, xz, yz). Entry (i, j)
  // takes the same products in the same order as (j, i) (a_i a_j = a_j a_i exactly), so summing one
  // of each pair gives the full matrix's values bit for bit at 6 of its 9 entries' cost.
  std::array<double, 6> second120{};
  static constexpr std::array<std::array<int, 2>, 6> kEntries{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - origin;
    const Vec3 b = mesh.vertices[t[1]] - origin;
    const Vec3 c = mesh.vertices[t[2]] - origin;
    const double d = a.dot(b.cross(c));
    const Vec3 s = a + b + c;
    six_volume += d;
    moment24 += d * s;
    for (std::size_t k = 0; k < kEntries.size(); ++k) {
      const int i = kEntries[k][0];
      const int j = kEntries[k][1];
      second120[k] += d * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
    }
  }
  MassProperties result;
  result.volume = six_volume / 6.0;
  if (six_volume == 0.0) return result;
  const Vec3 centre = moment24 / (4.0 * six_volume);  // (moment24 / 24) / (six_volume / 6)
  result.centroid = origin + centre;
  // Parallel-axis shift of the second moment to the centroid, then I = tr(C) Id - C.
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < kEntries.size(); ++k)
    second(kEntries[k][0], kEntries[k][1]) = second(kEntries[k][1], kEntries[k][0]) = second120[k];
  const Eigen::Matrix3d covariance = second / 120.0 - result.volume * centre * centre.transpose();
  result.inertia = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
  result.inertia = 0.5 * (result.inertia + result.inertia.transpose()).eval();
  return result;
}

VolumeCentroid volume_centroid(const Mesh& mesh) {
  // mass_properties' loop less the second moment: each sum takes the same terms in the same order.
  const Vec3 origin = reference_point(mesh);
  double six_volume = 0.0;
  Vec3 moment24 = Vec3::Zero();
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - origin;
    const Vec3 b = mesh.vertices[t[1]] - origin;
    const Vec3 c = mesh.vertices[t[2]] - origin;
    const double d = a.dot(b.cross(c));
    six_volume += d;
    moment24 += d * (a + b + c);
  }
  VolumeCentroid result;
  result.volume = six_volume / 6.0;
  if (six_volume == 0.0) return result;
  result.centroid = origin + moment24 / (4.0 * six_volume);
  return result;
}

double signed_volume(const Mesh& mesh) {
  const Vec3 origin = reference_point(mesh);
  double six_volume = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - origin;
    const Vec3 b = mesh.vertices[t[1]] - origin;
    const Vec3 c = mesh.vertices[t[2]] - origin;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

double tagged_area(const Mesh& mesh, FaceTag tag) {
  assert(mesh.tags.size() == mesh.triangles.size());
  double twice_area = 0.0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (mesh.tags[f] != tag) continue;
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.vertices[t[0]];
    twice_area += (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return 0.5 * twice_area;
}

double surface_area(const Mesh& mesh) {
  double twice_area = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    twice_area += (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return 0.5 * twice_area;
}

}  // namespace shatter
