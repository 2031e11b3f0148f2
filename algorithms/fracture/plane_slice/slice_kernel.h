#pragma once
/// The slicing kernel of recursive_slicing.h over MeshSlicer, shared by plane-slice's fractures and by
/// fem-lite's crack search (piece_counter.h), whose pieces are then the fragments themselves.
/// An attributed solid is cut as tracked pieces (corner_provenance.h): the corner values are
/// evaluated once, on the fragments.

#include "algorithms/core/corner_provenance.h"
#include "algorithms/core/fragment.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/result.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"

#include <string>
#include <vector>

namespace shatter {

/// Cuts pieces by planes (MeshSlicer), each side split into its volumes.
class SliceKernel {
 public:
  /// What a cut whose halves are closed but cross themselves at rounding scale counts as
  /// (MeshSlicer::self_intersecting).
  enum class RoundingCrossings {
    fail,  ///< a failed cut: the piece stays whole, so every piece passes the acceptance rule again
    keep,  ///< a cut made (counted in CutTally::self_intersecting): every plane cuts what it crosses
  };
  /// Tracks the corners through `provenance` when given (an attributed solid), else cuts plain meshes.
  explicit SliceKernel(CornerProvenance* provenance, RoundingCrossings crossings = RoundingCrossings::fail)
      : provenance_(provenance), crossings_(crossings) {}

  /// A closed piece with its volume and centroid (a piece may be cut again, so its second moments
  /// wait for the fragments: to_fragments).
  struct Piece {
    Mesh mesh;
    VolumeCentroid shape;
  };

  [[nodiscard]] Vec3 centroid(const Piece& piece) const { return piece.shape.centroid; }

  /// The volumes of `piece` below and above `plane`, appended to `below` and `above`; both left as
  /// they were when the plane does not cut the piece (or the cut could not be capped).
  void split(const Piece& piece, const Plane& plane, std::vector<Piece>& below, std::vector<Piece>& above) const;

  /// The volumes of `mesh` (each an outer shell with its cavities) as pieces.
  static void append_parts(Mesh&& mesh, std::vector<Piece>& out);

  /// The cuts made, missed and failed so far (a failed cut's piece was kept whole).
  [[nodiscard]] const CutTally& tally() const { return tally_; }
  /// Cuts the slicer could not cap; those pieces were kept whole.
  [[nodiscard]] int failed_cuts() const { return tally_.failed; }
  /// Why the first of them failed ("" when none did).
  [[nodiscard]] const std::string& first_failure() const { return first_failure_; }

 private:
  CornerProvenance* provenance_;
  RoundingCrossings crossings_;
  mutable MeshSlicer slicer_;
  mutable CutTally tally_;
  mutable std::string first_failure_;
};

/// The solid's volumes as pieces: tracked by `provenance` when given.
std::vector<SliceKernel::Piece> start_pieces(const Mesh& solid, const CornerProvenance* provenance);

/// The pieces as fragments with their mass properties, their corner values evaluated through
/// `provenance` when given.
Result<std::vector<Fragment>> to_fragments(std::vector<SliceKernel::Piece>&& pieces, const CornerProvenance* provenance);

}  // namespace shatter
