#include "algorithms/fracture/plane_slice/slice_kernel.h"

#include "algorithms/core/volume_components.h"

#include <utility>

namespace shatter {

void SliceKernel::split(const Piece& piece, const Plane& plane, std::vector<Piece>& below,
                        std::vector<Piece>& above) const {
  Mesh lower;
  Mesh upper;
  const SliceOutcome outcome = slicer_.slice(piece.mesh, plane, lower, upper, provenance_);
  switch (outcome) {
    case SliceOutcome::cut:
      if (slicer_.self_intersecting() && crossings_ == RoundingCrossings::fail) {
        if (tally_.failed++ == 0)
          first_failure_ = "every snap distance gave a half that intersects itself at rounding scale";
        return;
      }
      ++tally_.cuts;
      if (slicer_.snap_level() > 0) ++tally_.widened;
      if (slicer_.self_intersecting()) ++tally_.self_intersecting;
      break;
    case SliceOutcome::all_below:
    case SliceOutcome::all_above:
      ++tally_.misses;
      return;
    case SliceOutcome::failed:
      if (tally_.failed++ == 0) first_failure_ = slicer_.error();
      return;
  }
  append_parts(std::move(lower), below);
  append_parts(std::move(upper), above);
}

void SliceKernel::append_parts(Mesh&& mesh, std::vector<Piece>& out) {
  for (Mesh& part : volume_components(std::move(mesh))) {
    const VolumeCentroid shape = volume_centroid(part);
    out.push_back({std::move(part), shape});
  }
}

std::vector<SliceKernel::Piece> start_pieces(const Mesh& solid, const CornerProvenance* provenance) {
  std::vector<SliceKernel::Piece> pieces;
  SliceKernel::append_parts(provenance != nullptr ? provenance->tracked() : Mesh(solid), pieces);
  return pieces;
}

Result<std::vector<Fragment>> to_fragments(std::vector<SliceKernel::Piece>&& pieces,
                                           const CornerProvenance* provenance) {
  std::vector<Fragment> out;
  out.reserve(pieces.size());
  for (SliceKernel::Piece& p : pieces) {
    Mesh mesh = std::move(p.mesh);
    if (provenance != nullptr) {
      Result<Mesh> resolved = provenance->resolve(std::move(mesh));
      if (!resolved) return resolved.error();
      mesh = std::move(*resolved);
    }
    const MassProperties mass = mass_properties(mesh);
    out.push_back({std::move(mesh), mass});
  }
  return out;
}

}  // namespace shatter
