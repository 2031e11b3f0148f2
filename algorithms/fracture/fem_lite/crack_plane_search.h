#pragma once
/// Where fem-lite cracks: planes through the most stressed element centres, normal to the largest
/// principal stress, added until the cut gives the requested number of fragments.
///
/// Design note: the model says a crack opens where the largest principal stress exceeds the tensile
/// strength, across that stress. A fracturer must also honour the requested fragment count, so the
/// elements are taken most stressed first whether or not they exceed the strength (the count of those
/// that do is reported). A candidate whose centre lies within `spacing` cells of an earlier crack plane
/// (measured along that plane's normal) is skipped: the stress peak of one crack spreads over its
/// neighbours. Each accepted plane is cut into the pieces at once (PieceCounter), so the search stops
/// exactly when the fragment count is reached and a plane that adds no piece is dropped. When the
/// candidates run out first, the spacing is halved (twice) and then ignored, and the search goes on.
/// A plane that would cut off a piece smaller than `min_piece_share` of the mean fragment volume is
/// skipped (a sliver along an earlier plane or the surface); only if every candidate has been tried
/// without reaching the count are the skipped ones tried again with slivers allowed.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/fem_lite/element_stress.h"
#include "algorithms/fracture/fem_lite/hex_grid.h"
#include "algorithms/fracture/plane_slice/slice_kernel.h"

#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// Options of search_crack_planes.
struct CrackSearchOptions {
  int fragments = 1;                 ///< requested fragment count, >= 1
  double spacing = 1.0;              ///< cells, >= 0 (FemLiteSettings::crack_spacing)
  double tensile_strength = 3e6;     ///< Pa, only for the over_strength count
  std::uint64_t seed = 1;            ///< directions of unstressed elements (SplitMix64)
  /// Smallest piece a plane may cut off, share of the solid's volume / `fragments`, in [0, 1)
  /// (FemLiteSettings::min_piece_share); 0 allows any piece.
  double min_piece_share = 0.0;
};

/// The planes found and what they give.
struct CrackSearch {
  std::vector<Plane> planes;   ///< crack planes, most stressed first; each through an element centre (m)
  int fragments = 0;           ///< fragments the planes cut the solid into
  int over_strength = 0;       ///< elements whose largest principal stress exceeds the tensile strength
  int candidates_tried = 0;    ///< planes cut into the pieces (accepted or dropped)
};

/// Searches the crack planes of `solid` (closed, outward) from the element stresses of `grid`
/// (#E). Deterministic in `options.seed`. With `pieces`, it receives the pieces the planes cut the
/// solid into, as PlaneSliceFracturer::fracture_by_planes makes them: from a plain mesh, or with their
/// corners tracked through `provenance` when given (an attributed solid's; the planes are the same).
CrackSearch search_crack_planes(const Mesh& solid, const HexGrid& grid, std::span<const ElementStress> stresses,
                                const CrackSearchOptions& options, std::vector<SliceKernel::Piece>* pieces = nullptr,
                                CornerProvenance* provenance = nullptr);

}  // namespace shatter
