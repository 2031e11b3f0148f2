#pragma once
/// Building meshes from meshes: joining parts, reversing orientation, splitting into a triangle soup.

#include "algorithms/core/mesh.h"

namespace shatter {

/// Appends `part` to `into`: its vertices after those of `into`, its triangles with indices shifted
/// accordingly and their tags and attributes kept (`into` takes `part`'s attribute frame when it has
/// no triangles yet; otherwise the two must share it). No vertex is shared between the two.
void append_mesh(Mesh& into, const Mesh& part);

/// `mesh` with every triangle's orientation reversed (tags kept).
Mesh reversed_mesh(Mesh mesh);

/// `mesh` as a triangle soup: every triangle gets its own three vertices (same positions, same order,
/// tags kept), so no vertex is shared.
Mesh triangle_soup(const Mesh& mesh);

}  // namespace shatter
