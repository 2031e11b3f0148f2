#include "algorithms/core/corner_provenance.h"

#include <numeric>
#include <utility>

namespace shatter {

CornerProvenance::CornerProvenance(const Mesh& solid)
    : solid_(solid), solid_faces_(static_cast<std::int32_t>(solid.triangles.size())) {}

Mesh CornerProvenance::tracked() const {
  Mesh piece;
  piece.vertices = solid_.vertices;
  piece.triangles = solid_.triangles;
  piece.tags = solid_.tags;
  // No corner values and one placeholder slot: every routine that passes faces on (attribute_transfer.h)
  // then carries the per-face entry, which holds the record, and nothing else.
  piece.attributes.slots.resize(1);
  piece.attributes.slots[0].name = "record";
  piece.attributes.materials.resize(solid_.triangles.size());
  std::iota(piece.attributes.materials.begin(), piece.attributes.materials.end(), 0);
  return piece;
}

CornerProvenance::Cut CornerProvenance::cut_of(std::int32_t record) const {
  if (record >= solid_faces_) return cuts_[static_cast<std::size_t>(record - solid_faces_)];
  return {record, {CornerWeights{1.0, 0.0, 0.0}, CornerWeights{0.0, 1.0, 0.0}, CornerWeights{0.0, 0.0, 1.0}}};
}

std::int32_t CornerProvenance::mixed(std::int32_t parent, const std::array<CornerMix, 3>& mix) {
  const Cut from = cut_of(parent);
  Cut cut{from.face, {}};
  for (int i = 0; i < 3; ++i) {
    const CornerMix& m = mix[static_cast<std::size_t>(i)];
    const CornerWeights& a = from.weights[static_cast<std::size_t>(m.from)];
    const CornerWeights& b = from.weights[static_cast<std::size_t>(m.to)];
    CornerWeights& w = cut.weights[static_cast<std::size_t>(i)];
    if (m.from == m.to || m.t == 0.0) {
      w = a;
      continue;
    }
    for (std::size_t k = 0; k < 3; ++k) w[k] = a[k] + m.t * (b[k] - a[k]);
  }
  cuts_.push_back(cut);
  return solid_faces_ + static_cast<std::int32_t>(cuts_.size() - 1);
}

std::int32_t CornerProvenance::cap(const Vec3& outward_normal) {
  cap_normals_.push_back(outward_normal);
  return -static_cast<std::int32_t>(cap_normals_.size());
}

Mesh CornerProvenance::resolve(Mesh&& piece) const {
  Mesh out;
  copy_attribute_frame(solid_, out);
  const std::size_t faces = piece.triangles.size();
  const auto stride = static_cast<std::size_t>(solid_.attributes.layout.stride());
  const bool materials = !solid_.attributes.materials.empty();
  // Every face's values appended in order (reserved once; not zeroed first), the geometry the piece's
  // own, moved.
  MeshAttributes& attr = out.attributes;
  std::vector<double>& corners = attr.corners;
  corners.reserve(3 * faces * stride);
  if (materials) attr.materials.resize(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const std::int32_t record = piece.attributes.materials[f];
    if (record >= 0 && record < solid_faces_) {
      const auto source = static_cast<std::size_t>(record);
      const double* values = solid_.attributes.corner(source, 0);
      corners.insert(corners.end(), values, values + 3 * stride);
      if (materials) attr.materials[f] = solid_.attributes.materials[source];
      continue;
    }
    corners.resize(corners.size() + 3 * stride);
    double* values = corners.data() + corners.size() - 3 * stride;
    if (is_cap(record)) {
      const Triangle& t = piece.triangles[f];
      write_cut_corners(attr, cap_normals_[static_cast<std::size_t>(-record - 1)],
                        {piece.vertices[static_cast<std::size_t>(t[0])], piece.vertices[static_cast<std::size_t>(t[1])],
                         piece.vertices[static_cast<std::size_t>(t[2])]},
                        values);
      if (materials) attr.materials[f] = attr.cut.material;
      continue;
    }
    const Cut& cut = cuts_[static_cast<std::size_t>(record - solid_faces_)];
    const auto source = static_cast<std::size_t>(cut.face);
    for (std::size_t k = 0; k < 3; ++k) {
      const CornerWeights& w = cut.weights[k];
      interpolate_corners(solid_.attributes, source, Vec3(w[0], w[1], w[2]), values + k * stride);
    }
    if (materials) attr.materials[f] = solid_.attributes.materials[source];
  }
  out.vertices = std::move(piece.vertices);
  out.triangles = std::move(piece.triangles);
  out.tags = std::move(piece.tags);
  return out;
}

}  // namespace shatter
