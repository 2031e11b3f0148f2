#pragma once
// "voro++": Voronoi fracture with the cells computed by voro++ and cut from the solid by shatterbench's
// exact slicing kernel (MeshSlicer: exact side predicates, constrained Delaunay caps).

#include "algorithms/registry/registries.h"

namespace voro_plugin {

/// Adds the "voro++" fracturer to `registries`.
void register_voro(shatter::Registries& registries);

}  // namespace voro_plugin
