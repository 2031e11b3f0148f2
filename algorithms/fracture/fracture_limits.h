#pragma once
/// Checks of fracture inputs shared by every fracturer, with the documented limits. Every entry point
/// of a fracturer calls one of them before any geometry is computed, so an input an algorithm cannot
/// represent is an Error, never a crash (docs/limits.md, docs/stability.md).

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/fracture/fracturer.h"

#include <span>

namespace shatter {

/// The largest fragment count a fracturer accepts (memory grows linearly with it). A fracturer may
/// accept fewer (voronoi_fracturer.h, cgal_clip_fracturer.h); docs/limits.md gives the time at each.
inline constexpr int kMaxFragments = 100000;

/// The one input check of every fracturer: consistent attributes (check_attributes: an attributed
/// mesh must have been readied by prepare_cut_faces) and the acceptance rule (check_solid,
/// solid_check.h), which includes the representable coordinate range; `algorithm` names the fracturer
/// in the message.
/// `verdicts` remembers meshes that passed (FractureParams::verdicts). With `values` at_use the corner
/// values are left to the fracturer, which checks each where it reads it.
Status check_fracture_solid(const Mesh& solid, std::string_view algorithm, SelfIntersectionVerdicts* verdicts,
                            AttributeValues values = AttributeValues::checked);

/// 1 <= fragments <= `max_fragments` and an impact (if any) with a point in the coordinate range, a
/// finite direction and impulse and a radius in [0, kMaxCoordinate]: the request, not the solid.
Status check_fracture_request(const FractureParams& params, std::string_view algorithm,
                              int max_fragments = kMaxFragments);

/// check_fracture_request, then check_fracture_solid with params.verdicts.
Status check_fracture_params(const Mesh& solid, const FractureParams& params, std::string_view algorithm,
                             int max_fragments = kMaxFragments);

/// Error unless every plane has a point in the coordinate range and a non-zero normal whose
/// components are within it too.
Status check_planes(std::span<const Plane> planes);

}  // namespace shatter
