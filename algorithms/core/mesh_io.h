#pragma once
/// Reading and writing meshes as OFF and OBJ. Readers never crash on bad input: a malformed file gives
/// an Error naming the file and the line. Polygonal faces are triangulated (fan from the first vertex
/// for convex faces, ear clipping otherwise). Read meshes are tagged `FaceTag::surface`. A file past
/// the limits of mesh_limits.h (bytes, vertices, triangles) is refused before the memory it would need
/// is allocated: an OFF header's counts are checked before anything is reserved, an OBJ file's
/// statements are counted before it is parsed.

#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/result.h"

#include <filesystem>
#include <string>

namespace shatter {

/// Reads an OFF file (header `OFF`, counts, vertices, faces; comments with '#').
Result<Mesh> read_off(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Reads the vertices and faces of an OBJ file (other statements are ignored).
Result<Mesh> read_obj(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Reads by extension (.off or .obj, case-insensitive).
Result<Mesh> read_mesh(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Writes an OBJ with the cut faces in group `cut` and the surface faces in group `surface`.
Status write_obj(const Mesh& mesh, const std::filesystem::path& path);

/// Writes an OFF file.
Status write_off(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace shatter
