#pragma once
/// The acceptance rule: what every fracturer accepts as input and what everything it outputs satisfies.
///
/// Design note: one rule in one place. A mesh is a solid when its coordinates are finite and within
/// the representable range (representable_range.h); no triangle repeats an index or has zero area
/// (exactly collinear corners); every undirected edge is used by exactly two triangles in opposite
/// directions (closed, edge-manifold, consistently oriented); its shells describe a solid
/// (classify_shells: outward shells, possibly with the inward shells of cavities, none crossing, none
/// nested with one orientation), no shell is flat and the whole faces outward (positive volume); and
/// no two triangles intersect (self_intersection.h: triangles sharing an edge or a vertex, by position,
/// do not intersect there; touching anywhere else, or overlapping in one plane, does). Every
/// fracturer calls check_solid on its input and on nothing else, so all of them accept exactly the
/// same meshes, and their conformance test checks every fragment with it, so a fragment can always be
/// fractured again. validate_solid (mesh_validation.h) normalises a user's mesh first and then applies
/// the same rule.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"
#include "algorithms/core/self_intersection_verdicts.h"

#include <string_view>

namespace shatter {

/// Success when `mesh` satisfies the acceptance rule (see the design note), else one error line
/// "<who>: <the first violation>". Read-only. With `verdicts`, a mesh that passed is remembered by
/// its fingerprint and passes again at the cost of the fingerprint (the self-intersection test, the
/// costly part, is not repeated); without, every check runs.
Status check_solid(const Mesh& mesh, std::string_view who, SelfIntersectionVerdicts* verdicts);

}  // namespace shatter
