#pragma once
/// Converting an imported assimp scene into one Mesh (the rules are read_asset.h's): node transforms
/// applied, meshes merged, the attributes every mesh has kept, one material slot per material used.

#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/result.h"

#include <string>

struct aiScene;

namespace shatter {

/// The triangles of `scene` as one mesh; `name` prefixes every error. Checks the vertex and triangle
/// limits on the scene before converting, and finiteness of every value converted.
Result<Mesh> mesh_from_assimp_scene(const aiScene& scene, const std::string& name, const MeshReadLimits& limits);

}  // namespace shatter
