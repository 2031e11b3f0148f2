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

/// Reads the vertices, faces, normals, texture coordinates and materials of an OBJ file. A `v`
/// statement holds x y z, x y z w with w = 1, or x y z r g b (a vertex colour, checked and dropped);
/// `vn` holds x y z, `vt` u v or u v w (w dropped); an `f` statement holds at least 3 corners `v`,
/// `v/vt`, `v//vn` or `v/vt/vn` (negative indices count back from the last one read); `g` and `o`
/// name the group (`cut` tags its faces as cut faces, `repair` as repair faces).
///
/// Attributes (mesh_attributes.h), per triangle corner: normals when every face corner names a `vn`,
/// one UV set when every corner names a `vt`; a channel that only some corners have is dropped for
/// the whole mesh (a renderer cannot draw part of a UV layout; a file with none reads as before, with
/// no attributes). Normals are kept as written (not normalised). A `vt`/`vn` index out of range is an
/// error naming the line.
///
/// Materials: when any face follows a `usemtl`, each material name used becomes a slot (in order of
/// first use) and faces before the first `usemtl` get a slot "default"; without `usemtl` there are
/// no slots. `mtllib` names libraries relative to the OBJ's folder, read by read_mtl
/// (material_library.h) at that line: a library that does not exist is an error naming it (`file:line:
/// material library 'y.mtl' not found (looked for PATH)`), and so is a `usemtl` name that the file's
/// libraries lack (`file:line: material 'x' not in 'y.mtl'`). An OBJ without `mtllib` (some exporters
/// write none) gets one white slot per `usemtl` name. A slot takes the library's Kd, d/Tr and map_Kd;
/// the texture path is made relative to the OBJ's folder.
///
/// Smoothing groups, lines and points are skipped; free-form geometry (`curv`, `surf`) and unknown
/// statements are errors.
Result<Mesh> read_obj(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Reads by extension (.off or .obj, case-insensitive).
Result<Mesh> read_mesh(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Writes an OBJ with the surface faces in group `surface`, the cut faces in group `cut` and the faces
/// that mesh repair added in group `repair` (a group only when it has faces). Positions with 17
/// significant digits (read_obj gives them back exactly). A mesh without attributes is written as
/// positions and faces only. An attributed mesh adds a `vn` (normalised; a zero normal as written)
/// and a `vt` (UV set 0; OBJ has one) per triangle corner, corners written as `v/vt/vn`, and, when it
/// has material slots, `mtllib` and a `usemtl` before each run of faces of one material within a
/// group. The library named is `mtl_file` (the caller writes it, as a folder of fragments shares one)
/// or, when `mtl_file` is empty, `<name of path>.mtl` written beside the OBJ by write_mtl. Tangents
/// and UV sets past the first have no OBJ statement and are not written.
Status write_obj(const Mesh& mesh, const std::filesystem::path& path, const std::string& mtl_file = {});

/// Writes an OFF file.
Status write_off(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace shatter
