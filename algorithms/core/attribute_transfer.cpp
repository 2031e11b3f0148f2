#include "algorithms/core/attribute_transfer.h"

#include "algorithms/core/triangle_locator.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace shatter {
namespace {

std::size_t stride_of(const MeshAttributes& a) { return static_cast<std::size_t>(a.layout.stride()); }

/// Appends triangle (a, b, c) of `dst` with the tag and material of triangle `f` of `src`, and returns
/// how many values each of its corners must get next (0 when `src` carries none).
std::size_t start_triangle_from(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b,
                                std::int32_t c) {
  dst.add_triangle(a, b, c, src.tags[f]);
  if (src.attributes.empty()) return 0;
  if (!src.attributes.materials.empty()) dst.attributes.materials.push_back(src.attributes.materials[f]);
  return stride_of(src.attributes);
}

/// A plane's cut-face frame: its unit normal, the basis of cut_plane_basis and the tangent's handedness.
struct PlanarFrame {
  Vec3 given = Vec3::Zero();  // the normal as the caller gave it (any length)
  Vec3 n = Vec3::UnitZ();
  std::array<Vec3, 2> e{Vec3::UnitX(), Vec3::UnitY()};
  double handedness = 1.0;
};

/// The frame of `normal`. A cut's cap faces all share one normal, so the last frame is kept (one per
/// thread) instead of being rebuilt for every cap triangle.
const PlanarFrame& planar_frame(const Vec3& normal) {
  thread_local PlanarFrame last;
  if (normal == last.given && last.given != Vec3::Zero()) return last;
  last.given = normal;
  last.n = normal.normalized();
  last.e = cut_plane_basis(last.n);
  // Handedness: +1 when n is the canonical normal e1 x e2, -1 on the crack's other face.
  last.handedness = last.e[0].cross(last.e[1]).dot(last.n) >= 0.0 ? 1.0 : -1.0;
  return last;
}

/// Appends the corner values of a planar face with normal `normal` at positions `p`: the cut-face
/// dressing of the file comment of attribute_transfer.h (normal, planar UVs, tangent).
void append_planar_corners(MeshAttributes& attr, const Vec3& normal, const std::array<Vec3, 3>& p, double scale) {
  const std::size_t n = static_cast<std::size_t>(attr.layout.stride());
  attr.corners.resize(attr.corners.size() + 3 * n);
  write_planar_corners(attr.layout, normal, p, scale, attr.corners.data() + attr.corners.size() - 3 * n);
}

}  // namespace

PlanarDressing::PlanarDressing(const AttributeLayout& layout, const Vec3& normal, double scale)
    : scale_(scale),
      stride_(layout.stride()),
      uv_offset_(layout.uv_offset(0)),
      uv_sets_(layout.uv_sets),
      tangent_offset_(layout.tangent_offset()),
      normals_(layout.normals),
      tangents_(layout.tangents) {
  const PlanarFrame& frame = planar_frame(normal);
  e1_ = frame.e[0];
  e2_ = frame.e[1];
  if (layout.normals) std::copy_n(frame.n.data(), 3, fixed_.begin() + AttributeLayout::normal_offset());
  if (layout.tangents) {
    double* tangent = fixed_.data() + layout.tangent_offset();
    std::copy_n(frame.e[0].data(), 3, tangent);
    tangent[3] = frame.handedness;
  }
}

void PlanarDressing::write(const Vec3& a, const Vec3& b, const Vec3& c, double* out) const {
  // Channel by channel, the fixed values held in locals (which `out` cannot alias, so they are plain
  // stores rather than a copy call per corner): each value written once.
  const std::array<double, 3> normal{fixed_[0], fixed_[1], fixed_[2]};
  const double* t = fixed_.data() + tangent_offset_;
  const std::array<double, 4> tangent{t[0], t[1], t[2], t[3]};
  if (normals_ && uv_sets_ == 1 && tangents_) {
    // The layout of most textured assets (glTF's NORMAL, TEXCOORD_0, TANGENT): straight-line stores
    // at that layout's offsets (normal 0, UV 3, tangent 5, stride 9).
    assert(stride_ == 9 && uv_offset_ == 3 && tangent_offset_ == 5);
    for (const Vec3* q : {&a, &b, &c}) {
      const double u = q->dot(e1_) / scale_;
      const double v = q->dot(e2_) / scale_;
      out[0] = normal[0];
      out[1] = normal[1];
      out[2] = normal[2];
      out[3] = u;
      out[4] = v;
      out[5] = tangent[0];
      out[6] = tangent[1];
      out[7] = tangent[2];
      out[8] = tangent[3];
      out += 9;
    }
    return;
  }
  const auto stride = static_cast<std::size_t>(stride_);
  for (const Vec3* q : {&a, &b, &c}) {
    if (normals_)
      for (int i = 0; i < 3; ++i) out[AttributeLayout::normal_offset() + i] = normal[static_cast<std::size_t>(i)];
    const double u = q->dot(e1_) / scale_;
    const double v = q->dot(e2_) / scale_;
    for (int set = 0; set < uv_sets_; ++set) {
      out[uv_offset_ + 2 * set] = u;
      out[uv_offset_ + 2 * set + 1] = v;
    }
    if (tangents_)
      for (int i = 0; i < 4; ++i) out[tangent_offset_ + i] = tangent[static_cast<std::size_t>(i)];
    out += stride;
  }
}

void PlanarDressing::write_faces(const Mesh& mesh, std::size_t first, std::size_t count, double* out) const {
  const auto face_values = 3 * static_cast<std::size_t>(stride_);
  for (std::size_t f = first; f < first + count; ++f, out += face_values) {
    const Triangle& t = mesh.triangles[f];
    write(mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
          mesh.vertices[static_cast<std::size_t>(t[2])], out);
  }
}

PlanarDressing PlanarDressing::reversed() const {
  PlanarDressing other = *this;
  if (normals_)
    for (int i = 0; i < 3; ++i) other.fixed_[static_cast<std::size_t>(AttributeLayout::normal_offset() + i)] *= -1.0;
  if (tangents_) other.fixed_[static_cast<std::size_t>(tangent_offset_ + 3)] *= -1.0;
  return other;
}

void write_planar_corners(const AttributeLayout& layout, const Vec3& normal, const std::array<Vec3, 3>& p, double scale,
                          double* out) {
  PlanarDressing(layout, normal, scale).write(p[0], p[1], p[2], out);
}

PlanarDressing cut_face_dressing(const MeshAttributes& attr, const Vec3& outward_normal) {
  return PlanarDressing(attr.layout, outward_normal, attr.cut.uv_scale > 0.0 ? attr.cut.uv_scale : 1.0);
}

void copy_attribute_frame(const Mesh& src, Mesh& dst) {
  dst.attributes.layout = src.attributes.layout;
  dst.attributes.slots = src.attributes.slots;
  dst.attributes.cut = src.attributes.cut;
  dst.attributes.corners.clear();
  dst.attributes.materials.clear();
}

void add_triangle_from(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b, std::int32_t c,
                       const std::array<int, 3>& order) {
  const std::size_t n = start_triangle_from(dst, src, f, a, b, c);
  if (n == 0) return;
  CornerValues& out = dst.attributes.corners;
  if (order[0] == 0 && order[1] == 1 && order[2] == 2) {
    // The common case, a triangle copied whole: its three corners are contiguous.
    const double* values = src.attributes.corner(f, 0);
    out.insert(out.end(), values, values + 3 * n);
    return;
  }
  for (const int k : order) {
    const double* values = src.attributes.corner(f, k);
    out.insert(out.end(), values, values + n);
  }
}

void add_triangle_mixed(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b, std::int32_t c,
                        const std::array<CornerMix, 3>& mix) {
  const std::size_t n = start_triangle_from(dst, src, f, a, b, c);
  if (n == 0) return;
  CornerValues& out = dst.attributes.corners;
  for (const CornerMix& m : mix) {
    const double* from = src.attributes.corner(f, m.from);
    if (m.from == m.to || m.t == 0.0) {  // an original corner: its values as they are
      out.insert(out.end(), from, from + n);
      continue;
    }
    const double* to = src.attributes.corner(f, m.to);
    const std::size_t at = out.size();
    out.resize(at + n);
    for (std::size_t i = 0; i < n; ++i) out[at + i] = from[i] + m.t * (to[i] - from[i]);
  }
}

void add_triangle_weighted(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b, std::int32_t c,
                           const std::array<CornerWeights, 3>& weights) {
  const std::size_t n = start_triangle_from(dst, src, f, a, b, c);
  if (n == 0) return;
  CornerValues& out = dst.attributes.corners;
  for (const CornerWeights& w : weights) {
    out.resize(out.size() + n);
    interpolate_corners(src.attributes, f, Vec3(w[0], w[1], w[2]), out.data() + out.size() - n);
  }
}

std::array<Vec3, 2> cut_plane_basis(const Vec3& normal) {
  Vec3 n = normal.normalized();
  int largest = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) > std::abs(n[largest])) largest = i;
  if (n[largest] < 0.0) n = -n;
  // Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin (2017), listing 3.
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  return {Vec3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x()), Vec3(b, sign + n.y() * n.y() * a, -n.y())};
}

Vec2 cut_face_uv(const Vec3& p, const Vec3& normal, double uv_scale) {
  const std::array<Vec3, 2> e = cut_plane_basis(normal);
  return Vec2(p.dot(e[0]), p.dot(e[1])) / uv_scale;
}

void add_cut_triangle(Mesh& dst, std::int32_t a, std::int32_t b, std::int32_t c, const Vec3& outward_normal) {
  dst.add_triangle(a, b, c, FaceTag::cut);
  MeshAttributes& attr = dst.attributes;
  if (attr.empty()) return;
  if (!attr.slots.empty()) attr.materials.push_back(attr.cut.material);
  if (attr.layout.empty()) return;
  const std::size_t n = 3 * static_cast<std::size_t>(attr.layout.stride());
  attr.corners.resize(attr.corners.size() + n);
  cut_face_dressing(attr, outward_normal)
      .write(dst.vertices[static_cast<std::size_t>(a)], dst.vertices[static_cast<std::size_t>(b)],
             dst.vertices[static_cast<std::size_t>(c)], attr.corners.data() + attr.corners.size() - n);
}

double default_cut_uv_scale(const Mesh& mesh) {
  const Aabb box = bounding_box(mesh);
  if (!(box.min.x() <= box.max.x())) return 1.0;
  const double side = (box.max - box.min).maxCoeff();
  return side > 0.0 && std::isfinite(side) ? side : 1.0;
}

void prepare_cut_faces(Mesh& mesh, double uv_scale, const MaterialSlot* interior) {
  MeshAttributes& attr = mesh.attributes;
  if (attr.empty()) return;
  attr.cut.uv_scale = uv_scale > 0.0 ? uv_scale : default_cut_uv_scale(mesh);
  if (attr.cut.material >= 0) return;
  if (attr.slots.empty()) {
    MaterialSlot whole;
    whole.name = "default";
    attr.slots.push_back(whole);
    attr.materials.assign(mesh.triangles.size(), 0);
  }
  MaterialSlot slot;
  if (interior != nullptr) {
    slot = *interior;
  } else {
    slot.name = "interior";
    slot.base_color = {0.5, 0.5, 0.5, 1.0};
  }
  // A name no input slot has: "interior", else "interior_2", ...
  const std::string base = slot.name;
  for (int k = 2;
       std::any_of(attr.slots.begin(), attr.slots.end(), [&](const MaterialSlot& s) { return s.name == slot.name; });
       ++k)
    slot.name = base + "_" + std::to_string(k);
  attr.slots.push_back(std::move(slot));
  attr.cut.material = static_cast<std::int32_t>(attr.slots.size() - 1);
}

void reverse_corner_order(Mesh& mesh) {
  const std::size_t n = stride_of(mesh.attributes);
  if (n == 0) return;
  CornerValues& c = mesh.attributes.corners;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    std::swap_ranges(c.begin() + static_cast<std::ptrdiff_t>((3 * f + 1) * n),
                     c.begin() + static_cast<std::ptrdiff_t>((3 * f + 2) * n),
                     c.begin() + static_cast<std::ptrdiff_t>((3 * f + 2) * n));
}

void keep_triangles(Mesh& mesh, const std::vector<std::uint8_t>& keep) {
  const std::size_t n = stride_of(mesh.attributes);
  const bool materials = !mesh.attributes.materials.empty();
  std::size_t out = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!keep[f]) continue;
    mesh.triangles[out] = mesh.triangles[f];
    mesh.tags[out] = mesh.tags[f];
    if (materials) mesh.attributes.materials[out] = mesh.attributes.materials[f];
    if (n > 0 && out != f) {
      CornerValues& c = mesh.attributes.corners;
      std::copy_n(c.begin() + static_cast<std::ptrdiff_t>(3 * f * n), 3 * n, c.begin() + static_cast<std::ptrdiff_t>(3 * out * n));
    }
    ++out;
  }
  mesh.triangles.resize(out);
  mesh.tags.resize(out);
  if (materials) mesh.attributes.materials.resize(out);
  mesh.attributes.corners.resize(3 * out * n);
}

void interpolate_corners(const MeshAttributes& attributes, std::size_t f, const Vec3& weights, double* out) {
  const int n = attributes.layout.stride();
  const double* a = attributes.corner(f, 0);
  const double* b = attributes.corner(f, 1);
  const double* c = attributes.corner(f, 2);
  for (int i = 0; i < n; ++i) out[i] = weights[0] * a[i] + weights[1] * b[i] + weights[2] * c[i];
}

void transfer_attributes(const Mesh& from, Mesh& to) {
  if (from.attributes.empty()) return;
  copy_attribute_frame(from, to);
  const TriangleLocator locate(from);
  const std::size_t n = stride_of(from.attributes);
  MeshAttributes& attr = to.attributes;
  attr.corners.reserve(3 * n * to.triangles.size());
  const double scale = attr.cut.uv_scale > 0.0 ? attr.cut.uv_scale : default_cut_uv_scale(from);
  for (std::size_t f = 0; f < to.triangles.size(); ++f) {
    const Triangle& t = to.triangles[f];
    const std::array<Vec3, 3> p = {to.vertices[static_cast<std::size_t>(t[0])], to.vertices[static_cast<std::size_t>(t[1])],
                       to.vertices[static_cast<std::size_t>(t[2])]};
    const TriangleLocator::Hit hit = locate.nearest((p[0] + p[1] + p[2]) / 3.0);
    const auto source = static_cast<std::size_t>(std::max<std::int32_t>(hit.triangle, 0));
    if (!attr.slots.empty()) attr.materials.push_back(from.attributes.materials[source]);
    if (n == 0) continue;
    if (to.tags[f] != FaceTag::repair) {
      const Triangle& s = from.triangles[source];
      const Vec3& a = from.vertices[static_cast<std::size_t>(s[0])];
      const Vec3& b = from.vertices[static_cast<std::size_t>(s[1])];
      const Vec3& c = from.vertices[static_cast<std::size_t>(s[2])];
      for (const Vec3& q : p) {
        attr.corners.resize(attr.corners.size() + n);
        interpolate_corners(from.attributes, source, barycentric_coordinates(q, a, b, c),
                            attr.corners.data() + attr.corners.size() - n);
      }
      continue;
    }
    Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!(normal.squaredNorm() > 0.0)) normal = Vec3::UnitZ();
    append_planar_corners(attr, normal, {p[0], p[1], p[2]}, scale);
  }
}

Status check_attributes(const Mesh& mesh, const std::string& who, AttributeValues values) {
  const MeshAttributes& attr = mesh.attributes;
  if (attr.empty()) return {};
  const AttributeLayout& layout = attr.layout;
  const std::size_t faces = mesh.triangles.size();
  if (layout.uv_sets < 0 || layout.uv_sets > kMaxUvSets)
    return Error{who + ": " + std::to_string(layout.uv_sets) + " UV sets (at most " + std::to_string(kMaxUvSets) + ")"};
  if (layout.tangents && !layout.normals) return Error{who + ": tangents without normals"};
  if (attr.corners.size() != 3 * faces * stride_of(attr))
    return Error{who + ": " + std::to_string(attr.corners.size()) + " corner values for " + std::to_string(faces) +
                 " triangles of " + std::to_string(layout.stride()) + " values per corner"};
  if (attr.slots.empty() != attr.materials.empty() || (!attr.materials.empty() && attr.materials.size() != faces))
    return Error{who + ": " + std::to_string(attr.materials.size()) + " face materials for " + std::to_string(faces) +
                 " triangles and " + std::to_string(attr.slots.size()) + " material slots"};
  const auto slots = static_cast<std::int32_t>(attr.slots.size());
  if (attr.cut.material < 0 || attr.cut.material >= slots || !(attr.cut.uv_scale > 0.0) ||
      !std::isfinite(attr.cut.uv_scale))
    return Error{who + ": the attributes have no interior material or cut-face UV scale (prepare_cut_faces)"};
  for (std::size_t f = 0; f < attr.materials.size(); ++f)
    if (attr.materials[f] < 0 || attr.materials[f] >= slots)
      return Error{who + ": triangle " + std::to_string(f) + " has material " + std::to_string(attr.materials[f]) +
                   " of " + std::to_string(slots) + " slots"};
  if (values == AttributeValues::at_use || all_finite(attr.corners.data(), attr.corners.size())) return {};
  const std::size_t n = stride_of(attr);
  for (std::size_t i = 0; i < attr.corners.size(); ++i)
    if (!std::isfinite(attr.corners[i]))
      return Error{who + ": triangle " + std::to_string(i / (3 * n)) + " has a corner attribute that is not finite"};
  return {};
}

namespace {

using Lanes = std::array<double, 8>;

/// `lanes` with factor v - factor v added for each of the `count` values v at `values`: 0 for a finite
/// product and NaN otherwise, summed in 8 independent lanes (no reassociation needed, so the compiler
/// vectorises them). The lanes come and go by value: `values` cannot alias them, so they stay in
/// registers.
Lanes tally_scaled(Lanes lanes, const double* values, std::size_t count, double factor) {
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8)
    for (std::size_t k = 0; k < 8; ++k) {
      const double w = factor * values[i + k];
      lanes[k] += w - w;
    }
  for (; i < count; ++i) {
    const double w = factor * values[i];
    lanes[0] += w - w;
  }
  return lanes;
}

/// True when every lane is 0 (every value tallied was finite).
bool all_zero(const Lanes& lanes) {
  return std::all_of(lanes.begin(), lanes.end(), [](double lane) { return lane == 0.0; });
}

}  // namespace

bool all_finite(const double* values, std::size_t count) {
  // The first offender is sought only on failure (check_attributes).
  return all_zero(tally_scaled(Lanes{}, values, count, 1.0));
}

// A copy of a large piece's values (a megabyte for a mesh of 5,000 textured triangles) is bound by
// how many loads, stores and adds issue per cycle: on x86-64 with GCC it is built twice, for AVX2
// (32-byte vectors) and for the baseline (SSE2, 16 bytes), and the one the processor supports is chosen
// when the program loads. Elsewhere it is built once for the target: Debian's clang (14) names the
// function chosen at load "copy.ifunc", not as declared, so a caller in another file (the fuzzers'
// clang build) would not link.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SHATTER_AVX2_AND_BASELINE __attribute__((target_clones("avx2", "default")))
#else
#define SHATTER_AVX2_AND_BASELINE
#endif

SHATTER_AVX2_AND_BASELINE void FiniteTally::copy(const double* from, std::size_t count, double* to) {
  // The lanes in locals: `to` may not alias them, so they stay in registers.
  Lanes lanes = lanes_;
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8)
    for (std::size_t k = 0; k < 8; ++k) {
      const double v = from[i + k];
      to[i + k] = v;
      lanes[k] += v - v;
    }
  for (; i < count; ++i) {
    to[i] = from[i];
    lanes[0] += from[i] - from[i];
  }
  lanes_ = lanes;
}

void FiniteTally::add(const double* values, std::size_t count) { lanes_ = tally_scaled(lanes_, values, count, 1.0); }

bool FiniteTally::all_finite() const { return all_zero(lanes_); }

bool fracture_attributes_bounded(const Mesh& solid) {
  // 4 v is exact unless it overflows, which it does exactly when |v| > largest / 4 (or v is not finite).
  const MeshAttributes& attr = solid.attributes;
  if (!all_zero(tally_scaled(Lanes{}, attr.corners.data(), attr.corners.size(), 4.0))) return false;
  return attr.layout.empty() || cut_face_values_bounded(solid);
}

bool cut_face_values_bounded(const Mesh& solid) {
  constexpr double largest = std::numeric_limits<double>::max();
  const MeshAttributes& attr = solid.attributes;
  const double scale = attr.cut.uv_scale > 0.0 ? attr.cut.uv_scale : 1.0;  // as cut_face_dressing takes it
  double reach = 0.0;
  for (const Vec3& v : solid.vertices) reach = std::max(reach, v.cwiseAbs().maxCoeff());
  return std::isfinite(reach) && reach / scale <= largest / 16.0;
}

}  // namespace shatter
