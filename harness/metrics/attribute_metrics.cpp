#include "harness/metrics/attribute_metrics.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/random.h"
#include "algorithms/core/triangle_locator.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace shatter {
namespace {

/// Unit vector of `v`, or zero when `v` has no direction.
Vec3 unit(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 && std::isfinite(n) ? Vec3(v / n) : Vec3::Zero();
}

const Vec3& corner_position(const Mesh& mesh, std::size_t f, int k) {
  return mesh.vertices[static_cast<std::size_t>(mesh.triangles[f][static_cast<std::size_t>(k)])];
}

/// Area of triangle `f` of `mesh`, m^2.
double area_of(const Mesh& mesh, std::size_t f) {
  return 0.5 * (corner_position(mesh, f, 1) - corner_position(mesh, f, 0))
                   .cross(corner_position(mesh, f, 2) - corner_position(mesh, f, 0))
                   .norm();
}

/// Compares the values at `p` of fragment face `f` and input triangle `source`.
void compare_at(const Mesh& input, std::size_t source, const Mesh& piece, std::size_t f, const Vec3& p,
                AttributeMetrics& m) {
  const AttributeLayout& layout = input.attributes.layout;
  const int n = layout.stride();
  if (n == 0) return;
  std::vector<double> ours(static_cast<std::size_t>(n));
  std::vector<double> theirs(static_cast<std::size_t>(n));
  interpolate_corners(piece.attributes, f,
                      barycentric_coordinates(p, corner_position(piece, f, 0), corner_position(piece, f, 1),
                                              corner_position(piece, f, 2)),
                      ours.data());
  interpolate_corners(input.attributes, source,
                      barycentric_coordinates(p, corner_position(input, source, 0), corner_position(input, source, 1),
                                              corner_position(input, source, 2)),
                      theirs.data());
  if (layout.normals) {
    const int o = AttributeLayout::normal_offset();
    const Vec3 a = unit(Vec3(ours[o], ours[o + 1], ours[o + 2]));
    const Vec3 b = unit(Vec3(theirs[o], theirs[o + 1], theirs[o + 2]));
    m.normal_error = std::max(m.normal_error, (a - b).norm());
  }
  for (int set = 0; set < layout.uv_sets; ++set) {
    const auto o = static_cast<std::size_t>(layout.uv_offset(set));
    m.uv_error = std::max(m.uv_error, std::hypot(ours[o] - theirs[o], ours[o + 1] - theirs[o + 1]));
  }
}

/// Cap normals and materials of cut faces.
void check_caps(const Mesh& piece, AttributeMetrics& m) {
  const MeshAttributes& attr = piece.attributes;
  std::map<std::array<double, 3>, Vec3> cap_normal;  // corner normal -> area-weighted geometric normal
  for (std::size_t f = 0; f < piece.triangles.size(); ++f) {
    if (piece.tags[f] != FaceTag::cut) continue;
    if (!attr.materials.empty() && attr.materials[f] != attr.cut.material) ++m.material_errors;
    if (!attr.layout.normals) continue;
    const double* n = attr.corner(f, 0) + AttributeLayout::normal_offset();
    // try_emplace: a default Eigen vector is not zero.
    cap_normal.try_emplace({n[0], n[1], n[2]}, Vec3::Zero()).first->second += (corner_position(piece, f, 1) - corner_position(piece, f, 0))
                                          .cross(corner_position(piece, f, 2) - corner_position(piece, f, 0));
  }
  if (!attr.layout.normals) return;
  for (std::size_t f = 0; f < piece.triangles.size(); ++f) {
    if (piece.tags[f] != FaceTag::cut) continue;
    const double* first = attr.corner(f, 0) + AttributeLayout::normal_offset();
    const Vec3 plane = unit(cap_normal.at({first[0], first[1], first[2]}));
    for (int k = 0; k < 3; ++k) {
      const double* n = attr.corner(f, k) + AttributeLayout::normal_offset();
      m.cap_normal_error = std::max(m.cap_normal_error, (unit(Vec3(n[0], n[1], n[2])) - plane).norm());
    }
  }
}

}  // namespace

AttributeMetrics attribute_metrics(const Mesh& input, std::span<const Fragment> fragments,
                                   const AttributeMetricsOptions& options) {
  AttributeMetrics m;
  if (input.attributes.empty()) return m;
  m.measured = true;
  const TriangleLocator locate(input);

  // Surface faces of every fragment, with cumulative areas for area-weighted sampling.
  struct Face {
    std::size_t fragment;
    std::size_t face;
    std::int32_t source;
  };
  std::vector<Face> faces;
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const Mesh& piece = fragments[i].mesh;
    check_caps(piece, m);
    for (std::size_t f = 0; f < piece.triangles.size(); ++f) {
      if (piece.tags[f] == FaceTag::cut) continue;
      const Vec3 centroid =
          (corner_position(piece, f, 0) + corner_position(piece, f, 1) + corner_position(piece, f, 2)) / 3.0;
      const std::int32_t source = locate.nearest(centroid).triangle;
      if (source < 0) continue;
      const MeshAttributes& attr = piece.attributes;
      if (!attr.materials.empty() && !input.attributes.materials.empty() &&
          attr.materials[f] != input.attributes.materials[static_cast<std::size_t>(source)])
        ++m.material_errors;
      if (piece.tags[f] != FaceTag::surface) continue;
      total += area_of(piece, f);
      faces.push_back({i, f, source});
      cumulative.push_back(total);
    }
  }
  if (faces.empty() || !(total > 0.0) || options.samples <= 0) return m;

  SplitMix64 rng(options.seed);
  for (int s = 0; s < options.samples; ++s) {
    const double pick = rng.uniform() * total;
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), pick);
    const Face& face = faces[static_cast<std::size_t>(std::min<std::ptrdiff_t>(
        it - cumulative.begin(), static_cast<std::ptrdiff_t>(faces.size()) - 1))];
    const Mesh& piece = fragments[face.fragment].mesh;
    // A uniform point of the triangle (square-root parametrisation).
    const double r1 = std::sqrt(rng.uniform());
    const double r2 = rng.uniform();
    const Vec3 p = (1.0 - r1) * corner_position(piece, face.face, 0) +
                   r1 * (1.0 - r2) * corner_position(piece, face.face, 1) + r1 * r2 * corner_position(piece, face.face, 2);
    compare_at(input, static_cast<std::size_t>(face.source), piece, face.face, p, m);
    ++m.samples;
  }
  return m;
}

}  // namespace shatter
