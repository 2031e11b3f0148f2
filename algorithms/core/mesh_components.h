#pragma once
/// Connected parts of a mesh.

#include "algorithms/core/mesh.h"

#include <vector>

namespace shatter {

/// Splits `mesh` into its connected parts (triangles joined through shared vertices), each with only
/// the vertices it uses, triangles in their original order. Parts that touch only at a vertex count as
/// one part. Returns one part (the mesh itself, compacted) when the mesh is connected.
std::vector<Mesh> connected_components(const Mesh& mesh);

/// Same, consuming the mesh: a connected mesh is moved out without a copy.
std::vector<Mesh> connected_components(Mesh&& mesh);

}  // namespace shatter
