#pragma once
/// plane-slice: recursive slicing by random planes through the piece (seed section 8.1), caps by
/// constrained Delaunay triangulation, disconnected parts split into their own fragments.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/fracturer_registry.h"

#include <span>

namespace shatter {

/// The plane-slice fracturer; it cuts by given planes too (PlaneCutting).
class PlaneSliceFracturer final : public Fracturer, public PlaneCutting {
 public:
  [[nodiscard]] std::string_view name() const override { return "plane-slice"; }
  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid,
                                                       const FractureParams& params) const override;
  /// Its own recursive schedule (fragments and seed of `params`).
  [[nodiscard]] Result<std::optional<CutPlan>> cut_plan(const Mesh& solid,
                                                        const FractureParams& params) const override;
  /// This fracturer: it cuts by given planes.
  [[nodiscard]] const PlaneCutting* plane_cutting() const override { return this; }
  /// fracture_by_planes(solid, planes).
  [[nodiscard]] Result<std::vector<Fragment>> cut_by_planes(const Mesh& solid,
                                                            std::span<const Plane> planes) const override;
  /// What fracture_by_planes does when a plane crosses a piece but the cut cannot be made soundly
  /// (mesh_slicer.h, docs/plugins.md "The cutting kernel").
  enum class FailedCut {
    refuse,      ///< every cut is made: one whose halves cross themselves at rounding scale is kept
                 ///< (CutTally::self_intersecting), one that cannot be capped fails the call with
                 ///< the count and the reason (the default)
    keep_whole,  ///< a cut that cannot be capped, or whose halves cross themselves, leaves that piece
                 ///< whole for that plane (CutTally::failed): every piece passes the acceptance rule
  };
  /// Cuts `solid` by each plane in turn (every piece a plane crosses is split; a plane that misses a
  /// piece leaves it whole); a cut that cannot be made as `failed` says; an error once the pieces
  /// outnumber `max_fragments` (the documented kMaxFragments; tests pass smaller). `verdicts` as
  /// FractureParams::verdicts. `tally`, when given, receives what the planes did (mesh_slicer.h).
  [[nodiscard]] Result<std::vector<Fragment>> fracture_by_planes(const Mesh& solid, std::span<const Plane> planes,
                                                                 int max_fragments = kMaxFragments,
                                                                 SelfIntersectionVerdicts* verdicts = nullptr,
                                                                 FailedCut failed = FailedCut::refuse,
                                                                 CutTally* tally = nullptr) const;
};

/// Registers "plane-slice" (no settings).
void register_plane_slice(FracturerRegistry& registry);

}  // namespace shatter
