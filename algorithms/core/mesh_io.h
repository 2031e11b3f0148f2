#pragma once
/// Reading and writing meshes as OFF and OBJ. Readers never crash on bad input: a malformed file gives
/// an Error naming the file and the line. Files are read through read_file_bounded (bounded_read.h)
/// and split into lines by mesh_text.h, so "\n", "\r\n" and a lone "\r" all end a line. Numbers are
/// strict: every number is read whole as a finite double ("1,5", "foo", "nan", "1e400" are errors),
/// and a vertex has exactly the numbers its format allows. Polygonal faces are triangulated by
/// polygon_triangulation.h in O(n log n). Read meshes are tagged `FaceTag::surface` (OBJ faces in
/// group `cut` are tagged `FaceTag::cut`, in group `repair` `FaceTag::repair`). A file past the limits of mesh_limits.h (bytes, vertices,
/// triangles, polygon corners) is refused before the memory it would need is allocated: an OFF
/// header's counts are checked before anything is reserved, an OBJ statement is counted as it is
/// read.

#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/result.h"

#include <filesystem>
#include <string>

namespace shatter {

/// Reads an OFF file (header `OFF`, counts, vertices, faces; comments with '#'). The header may be
/// OFF, COFF, NOFF, STOFF or their combinations (Geomview's order ST, C, N): a vertex line then holds
/// exactly x y z plus 3 normal numbers (N), 3 or 4 colour numbers (C) and 2 texture numbers (ST), and
/// only x y z are kept. A face line may end with up to 4 colour numbers.
Result<Mesh> read_off(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Reads the vertices and faces of an OBJ file. A `v` statement holds x y z, x y z w with w = 1, or
/// x y z r g b (a vertex colour, checked and dropped); an `f` statement holds at least 3 corners
/// `v`, `v/vt`, `v//vn` or `v/vt/vn` (negative indices count back from the last vertex); `g` and `o`
/// name the group (`cut` tags its faces as cut faces, `repair` as repair faces). Texture coordinates, normals, materials,
/// smoothing groups, lines and points are skipped; free-form geometry (`curv`, `surf`) and unknown
/// statements are errors.
Result<Mesh> read_obj(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Reads by extension (.off or .obj, case-insensitive).
Result<Mesh> read_mesh(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Writes an OBJ with the surface faces in group `surface`, the cut faces in group `cut` and the faces
/// that mesh repair added in group `repair` (a group only when it has faces).
Status write_obj(const Mesh& mesh, const std::filesystem::path& path);

/// Writes an OFF file.
Status write_off(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace shatter
