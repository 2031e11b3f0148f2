#pragma once
/// Deferred attributes for a fracture that cuts a solid again and again (recursive slicing): the cut
/// pieces carry, per face, only a record of where its corners came from, and the corner values are
/// evaluated once, on the final fragments.
///
/// Design note: copying every face's corner values (a textured asset: 9 doubles a corner) through
/// each level of a recursive cut costs as much as the geometry itself, although most faces are only
/// passed on whole. A tracked piece is an ordinary mesh whose per-face material entry names a record
/// instead of a material slot; it has no corner values and no slots (per-face entries alone make its
/// attributes non-empty), so passing a face on copies one int and a new piece copies no slot.
/// A record is one of three kinds:
///   - 0..F-1: face r of the solid, its corners as they are;
///   - F..: a face cut from solid face `face`, each corner a barycentric weight triple over that
///     face's corners (a corner at a crossing mixes its parent corners' weights at the crossing's
///     parameter, the rule attribute_transfer.h applies to the values, so the result is the same
///     linear interpolation);
///   - negative: a cap of a cut with its outward normal, dressed as a cut face at the end (a cap face
///     cut again stays a cap of the same plane).
/// The records grow with the number of cut faces only (those a plane crosses), not with the solid.

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace shatter {

/// The records of one fracture of one attributed solid (single-threaded: one per fracture).
class CornerProvenance {
 public:
  /// Tracks `solid`, which carries attributes and must outlive this object.
  explicit CornerProvenance(const Mesh& solid, std::string who = "fracture");

  /// The solid's geometry and tags as a tracked piece (each face its own record).
  [[nodiscard]] Mesh tracked() const;

  /// The record of a face cut from a face of record `parent` (not a cap), corner i mixed as `mix[i]`
  /// says over the parent face's corners.
  std::int32_t mixed(std::int32_t parent, const std::array<CornerMix, 3>& mix);

  /// The records of one cut's cap faces: first for the side whose caps face along `normal` (any
  /// non-zero length), second for the side whose caps face against it. One call per cut, each record
  /// shared by all cap faces of its side.
  std::array<std::int32_t, 2> caps(const Vec3& normal);

  /// `piece` (a tracked piece) with the solid's attribute frame and every corner evaluated. No value
  /// that is not finite is returned: each is checked as it is written (the solid's values are read
  /// here, so a fracture that tracks them need not check them first: check_attributes'
  /// AttributeValues::at_use); an Error names the first solid triangle with a value that is not
  /// finite, or says that a value overflowed.
  [[nodiscard]] Result<Mesh> resolve(Mesh&& piece) const;

  /// True when `record` names a cap.
  [[nodiscard]] static bool is_cap(std::int32_t record) { return record < 0; }

 private:
  struct Cut {
    std::int32_t face;                    // face of the solid
    std::array<CornerWeights, 3> weights; // per corner, over that face's corners
  };

  const Mesh& solid_;
  std::string who_;  // names the fracture in resolve's error
  std::int32_t solid_faces_;
  // True when no cap value resolve writes can overflow, decided from the solid's positions
  // (cut_face_values_bounded); otherwise resolve checks the caps' values too.
  bool caps_bounded_;
  std::vector<Cut> cuts_;          // record solid_faces_ + i
  std::vector<PlanarDressing> cap_dressings_;  // record -(i + 1): its cut-face dressing
};

}  // namespace shatter
