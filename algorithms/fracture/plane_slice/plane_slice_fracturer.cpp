#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

#include "algorithms/core/corner_provenance.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/plane_slice/slice_kernel.h"
#include "algorithms/fracture/recursive_slicing.h"

#include <algorithm>
#include <memory>
#include <optional>

namespace shatter {
namespace {

/// The provenance records of one fracture of `solid`, when it carries attributes.
std::optional<CornerProvenance> provenance_for(const Mesh& solid) {
  if (!has_attributes(solid)) return std::nullopt;
  return std::optional<CornerProvenance>(std::in_place, solid, "plane-slice");
}

}  // namespace

Result<std::vector<Fragment>> PlaneSliceFracturer::fracture(const Mesh& solid,
                                                            const FractureParams& params) const {
  // The corner values are checked where the fragments read them (CornerProvenance::resolve).
  if (Status s = check_fracture_request(params, "plane-slice"); !s) return s.error();
  if (Status s = check_fracture_solid(solid, "plane-slice", params.verdicts, AttributeValues::at_use); !s)
    return s.error();
  std::optional<CornerProvenance> provenance = provenance_for(solid);
  CornerProvenance* tracking = provenance ? &*provenance : nullptr;
  const SliceKernel kernel(tracking);
  return to_fragments(slice_recursively(kernel, start_pieces(solid, tracking), params.fragments, params.seed),
                      tracking);
}

Result<std::vector<Fragment>> PlaneSliceFracturer::cut_by_planes(const Mesh& solid,
                                                                 std::span<const Plane> planes) const {
  return fracture_by_planes(solid, planes);
}

Result<std::vector<Fragment>> PlaneSliceFracturer::fracture_by_planes(const Mesh& solid, std::span<const Plane> planes,
                                                                      int max_fragments,
                                                                      SelfIntersectionVerdicts* verdicts,
                                                                      FailedCut failed, CutTally* tally) const {
  if (Status s = check_fracture_solid(solid, "plane-slice", verdicts, AttributeValues::at_use); !s)
    return s.error();
  if (Status s = check_planes(planes); !s) return s.error();
  std::optional<CornerProvenance> provenance = provenance_for(solid);
  CornerProvenance* tracking = provenance ? &*provenance : nullptr;
  // Every cut made when the caller must have them all; a cut whose halves cross themselves at
  // rounding scale leaves its piece whole when the caller keeps such pieces whole anyway.
  const SliceKernel kernel(tracking, failed == FailedCut::refuse ? SliceKernel::RoundingCrossings::keep
                                                                 : SliceKernel::RoundingCrossings::fail);
  auto pieces = slice_by_planes(kernel, start_pieces(solid, tracking), planes,
                                static_cast<std::size_t>(std::max(max_fragments, 1)));
  if (tally != nullptr) *tally = kernel.tally();
  if (!pieces) return Error{"plane-slice: " + pieces.error().message};
  // A plane that misses a piece leaves it whole by design; a cut that crossed a piece but could not
  // be made would leave fewer fragments than the planes make, so it fails the whole call.
  if (kernel.failed_cuts() > 0 && failed == FailedCut::refuse)
    return Error{"plane-slice: " + std::to_string(kernel.failed_cuts()) +
                 (kernel.failed_cuts() == 1 ? " cut" : " cuts") + " through a piece could not be made (" +
                 kernel.first_failure() + "); no fragments are returned"};
  return to_fragments(std::move(*pieces), tracking);
}

Result<std::optional<CutPlan>> PlaneSliceFracturer::cut_plan(const Mesh& solid, const FractureParams& params) const {
  if (Status s = check_fracture_params(solid, params, "plane-slice"); !s) return s.error();
  return std::optional<CutPlan>(RecursiveCutSchedule{params.fragments, params.seed});
}

void register_plane_slice(FracturerRegistry& registry) {
  registry.add("plane-slice", "recursive random plane cuts, constrained Delaunay caps (fast)", {},
               [](const PluginSettings& settings) -> Result<std::unique_ptr<Fracturer>> {
                 if (Status s = SettingsReader("plane-slice", settings, {}).check_keys(); !s) return s.error();
                 return std::unique_ptr<Fracturer>(std::make_unique<PlaneSliceFracturer>());
               });
}

}  // namespace shatter
