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
  out.vertices = std::move(piece.vertices);
  copy_attribute_frame(solid_, out);
  const std::size_t faces = piece.triangles.size();
  out.triangles.reserve(faces);
  out.tags.reserve(faces);
  if (!solid_.attributes.materials.empty()) out.attributes.materials.reserve(faces);
  out.attributes.corners.reserve(3 * faces * static_cast<std::size_t>(solid_.attributes.layout.stride()));
  for (std::size_t f = 0; f < faces; ++f) {
    const Triangle& t = piece.triangles[f];
    const std::int32_t record = piece.attributes.materials[f];
    if (is_cap(record)) {
      add_cut_triangle(out, t[0], t[1], t[2], cap_normals_[static_cast<std::size_t>(-record - 1)]);
    } else if (record < solid_faces_) {
      add_triangle_from(out, solid_, static_cast<std::size_t>(record), t[0], t[1], t[2]);
    } else {
      const Cut& cut = cuts_[static_cast<std::size_t>(record - solid_faces_)];
      add_triangle_weighted(out, solid_, static_cast<std::size_t>(cut.face), t[0], t[1], t[2], cut.weights);
    }
  }
  return out;
}

}  // namespace shatter
