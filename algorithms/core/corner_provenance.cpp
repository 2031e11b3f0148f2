#include "algorithms/core/corner_provenance.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace shatter {

CornerProvenance::CornerProvenance(const Mesh& solid, std::string who)
    : solid_(solid),
      who_(std::move(who)),
      solid_faces_(static_cast<std::int32_t>(solid.triangles.size())),
      caps_bounded_(cut_face_values_bounded(solid)) {}

Mesh CornerProvenance::tracked() const {
  Mesh piece;
  piece.vertices = solid_.vertices;
  piece.triangles = solid_.triangles;
  piece.tags = solid_.tags;
  // No corner values and no material slot, only the per-face entries, which hold the records: every
  // routine that passes faces on (attribute_transfer.h) carries them and nothing else.
  piece.attributes.materials.resize(solid_.triangles.size());
  std::iota(piece.attributes.materials.begin(), piece.attributes.materials.end(), 0);
  return piece;
}

std::int32_t CornerProvenance::mixed(std::int32_t parent, const std::array<CornerMix, 3>& mix) {
  // The new record is written in place: room is made first, so `from` (which may point into the
  // records) stays valid.
  if (cuts_.size() == cuts_.capacity()) cuts_.reserve(2 * cuts_.size() + 64);
  static constexpr std::array<CornerWeights, 3> whole_face{CornerWeights{1.0, 0.0, 0.0}, CornerWeights{0.0, 1.0, 0.0},
                                                           CornerWeights{0.0, 0.0, 1.0}};
  const bool cut_before = parent >= solid_faces_;
  const Cut* parent_cut = cut_before ? &cuts_[static_cast<std::size_t>(parent - solid_faces_)] : nullptr;
  const std::array<CornerWeights, 3>& from = cut_before ? parent_cut->weights : whole_face;
  Cut& cut = cuts_.emplace_back();
  cut.face = cut_before ? parent_cut->face : parent;
  for (int i = 0; i < 3; ++i) {
    const CornerMix& m = mix[static_cast<std::size_t>(i)];
    const CornerWeights& a = from[static_cast<std::size_t>(m.from)];
    const CornerWeights& b = from[static_cast<std::size_t>(m.to)];
    CornerWeights& w = cut.weights[static_cast<std::size_t>(i)];
    if (m.from == m.to || m.t == 0.0) {
      w = a;
      continue;
    }
    for (std::size_t k = 0; k < 3; ++k) w[k] = a[k] + m.t * (b[k] - a[k]);
  }
  return solid_faces_ + static_cast<std::int32_t>(cuts_.size() - 1);
}

std::array<std::int32_t, 2> CornerProvenance::caps(const Vec3& normal) {
  // The two sides share the plane's frame: one dressing is built, the other is its reverse.
  if (cap_dressings_.capacity() - cap_dressings_.size() < 2) cap_dressings_.reserve(2 * cap_dressings_.size() + 32);
  const PlanarDressing& along = cap_dressings_.emplace_back(cut_face_dressing(solid_.attributes, normal));
  cap_dressings_.push_back(along.reversed());
  const auto last = static_cast<std::int32_t>(cap_dressings_.size());
  return {-(last - 1), -last};
}

Result<Mesh> CornerProvenance::resolve(Mesh&& piece) const {
  Mesh out;
  copy_attribute_frame(solid_, out);
  const std::size_t faces = piece.triangles.size();
  const auto stride = static_cast<std::size_t>(solid_.attributes.layout.stride());
  const std::size_t face_values = 3 * stride;
  const bool materials = !solid_.attributes.materials.empty();
  const std::vector<std::int32_t>& records = piece.attributes.materials;
  // The geometry is the piece's own, moved.
  MeshAttributes& attr = out.attributes;
  if (materials) attr.materials.resize(faces);
  if (stride == 0) {
    if (!materials) return Error{who_ + ": a tracked solid carries neither corner values nor materials"};
    // Materials only: no corner value to evaluate (and no array to point into).
    for (std::size_t f = 0; f < faces; ++f) {
      const std::int32_t record = records[f];
      attr.materials[f] = is_cap(record)             ? attr.cut.material
                          : record < solid_faces_ ? solid_.attributes.materials[static_cast<std::size_t>(record)]
                                                  : solid_.attributes.materials[static_cast<std::size_t>(
                                                        cuts_[static_cast<std::size_t>(record - solid_faces_)].face)];
    }
    out.vertices = std::move(piece.vertices);
    out.triangles = std::move(piece.triangles);
    out.tags = std::move(piece.tags);
    return out;
  }
  // Every face's values appended in order to one array reserved once, each run of faces written in
  // place after one resize (which does not zero: CornerValues) and each value tallied as it is written
  // (FiniteTally): a run of whole faces is one copy, the whole faces' values (most of a large piece's)
  // are read once and written once, and no value is read again to be checked.
  CornerValues& corners = attr.corners;
  corners.reserve(faces * face_values);
  const double* solid_values = solid_.attributes.corners.data();
  const auto whole = [&](std::size_t face) {
    return records[face] >= 0 && records[face] < solid_faces_;
  };
  FiniteTally tally;
  std::size_t f = 0;
  while (f < faces) {
    const std::int32_t record = records[f];
    std::size_t run = 1;
    if (whole(f)) {
      // A run of whole solid faces in the solid's order (slicing keeps the order of the faces it passes
      // on): one copy for the run.
      while (f + run < faces && records[f + run] == record + static_cast<std::int32_t>(run) &&
             record + static_cast<std::int32_t>(run) < solid_faces_)
        ++run;
      const auto source = static_cast<std::size_t>(record);
      const std::size_t at = corners.size();
      corners.resize(at + run * face_values);
      tally.copy(solid_values + source * face_values, run * face_values, corners.data() + at);
      if (materials)
        std::copy_n(solid_.attributes.materials.begin() + static_cast<std::ptrdiff_t>(source), run,
                    attr.materials.begin() + static_cast<std::ptrdiff_t>(f));
      f += run;
      continue;
    }
    while (f + run < faces && !whole(f + run)) ++run;
    const std::size_t at = corners.size();
    corners.resize(at + run * face_values);
    double* out_values = corners.data() + at;
    const std::size_t end = f + run;
    while (f < end) {
      const std::int32_t r = records[f];
      if (is_cap(r)) {
        // A run of cap faces of one side of one cut (a cut adds its caps together): dressed in one call.
        std::size_t caps = 1;
        while (f + caps < end && records[f + caps] == r) ++caps;
        cap_dressings_[static_cast<std::size_t>(-r - 1)].write_faces(piece, f, caps, out_values);
        if (!caps_bounded_) tally.add(out_values, caps * face_values);
        if (materials)
          std::fill_n(attr.materials.begin() + static_cast<std::ptrdiff_t>(f), caps, attr.cut.material);
        f += caps;
        out_values += caps * face_values;
        continue;
      }
      const Cut& cut = cuts_[static_cast<std::size_t>(r - solid_faces_)];
      const auto source = static_cast<std::size_t>(cut.face);
      // The weighted sum of interpolate_corners, inline: the same operations in the same order.
      const double* a = solid_values + source * face_values;
      const double* b = a + stride;
      const double* c = b + stride;
      for (std::size_t k = 0; k < 3; ++k) {
        const CornerWeights& w = cut.weights[k];
        double* corner = out_values + k * stride;
        for (std::size_t i = 0; i < stride; ++i) corner[i] = w[0] * a[i] + w[1] * b[i] + w[2] * c[i];
      }
      tally.add(out_values, face_values);
      if (materials) attr.materials[f] = solid_.attributes.materials[source];
      ++f;
      out_values += face_values;
    }
  }
  if (!tally.all_finite()) {
    // The offending solid triangle, found only now; otherwise a weighted sum of values near the largest
    // doubles, or a cut face's UV of a position far out against a tiny UV scale, overflowed.
    if (Status s = check_attributes(solid_, who_); !s) return s.error();
    return Error{who_ + ": " + kAttributeOverflow};
  }
  out.vertices = std::move(piece.vertices);
  out.triangles = std::move(piece.triangles);
  out.tags = std::move(piece.tags);
  return out;
}

}  // namespace shatter
