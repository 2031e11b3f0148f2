#pragma once
/// Dressing a generated mesh as a textured asset: flat normals, box-projected UVs, tangents and one
/// material, so that built-in cases can carry attributes like an artist's mesh.
///
/// Box projection: each triangle is mapped along the axis its normal is closest to; looking at the
/// face from outside, u runs along the face to the right and v upwards (+z for the side faces, +y for
/// top and bottom), in metres divided by `uv_scale`. Across the edge of two faces mapped along
/// different axes the UVs jump: a seam, which per-corner attributes keep without opening the mesh.

#include "algorithms/core/mesh.h"

namespace shatter {

/// Gives every triangle of `mesh` (which must carry no attributes yet) a flat per-corner normal, one
/// box-projected UV set (metres per UV unit: `uv_scale` > 0), a tangent along +u and `material` as
/// its only material slot. Call prepare_cut_faces (attribute_transfer.h) before fracturing it.
void apply_box_mapping(Mesh& mesh, double uv_scale, const MaterialSlot& material);

}  // namespace shatter
