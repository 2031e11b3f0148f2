#pragma once
/// Reading any mesh asset into one Mesh: the project's own strict readers for OFF and OBJ
/// (mesh_io.h), and the Open Asset Import Library (assimp) for glTF 2.0 (.gltf, .glb), FBX, PLY, STL,
/// COLLADA (.dae), 3DS and every other format assimp imports.
///
/// Design note. What a fracture needs from a game asset is one triangle mesh in world space with its
/// per-corner attributes (mesh_attributes.h): the scene graph, cameras, lights, skins and animations
/// are not kept. assimp runs with Triangulate, SortByPType (point and line primitives removed) and
/// ValidateDataStructure; every node's accumulated transform is applied to the meshes it holds
/// (normals by the inverse transpose, tangents by the matrix, both renormalised; a mirroring transform
/// reverses the triangles' corner order so they stay outward), and all meshes are merged into one
/// (vertices are not welded: validate_solid welds positions). The attribute layout is what every mesh
/// has: normals when all have normals, the UV sets (2D, at most kMaxUvSets) all have, tangents when all
/// have tangents and normals, the handedness w = +1 or -1 from the sign of dot(cross(n, t), b) of the
/// bitangent assimp gives. UVs are assimp's (v pointing up, as OBJ writes them; glTF's v is flipped on
/// import and write_fragments_glb flips it back). One material slot per aiMaterial the merged meshes
/// use, in order of first use, named as the file names it ("material_N" when unnamed, "_2", ... added
/// to repeat names): base colour from the glTF base colour factor, else the diffuse colour with the
/// opacity as alpha (clamped to [0, 1]); base colour texture (else the diffuse texture) as a path
/// relative to the asset, or, for an embedded texture ("*N", or a name the file embeds), its encoded
/// bytes in base_color_image (an uncompressed embedded texture has no encoding to keep and is dropped).
/// Slots sharing one embedded texture share one TextureImage. assimp stores positions in single
/// precision, so an asset's positions are its floats widened to double.
///
/// Before assimp: content that the extension's importers do not recognise is refused at once (assimp
/// would try every other format's detection, seconds on a few kilobytes); a .glb must be a
/// well-formed container (magic, version 2, lengths within the data: assimp allocates what a chunk
/// header claims before checking it); glTF JSON must parse strictly (UTF-8 included: assimp 5.2 crashes
/// on a mimeType that is not), accessors and buffer views must lie within their data (the
/// specification's bounds, which assimp 5.2 does not check before copying), an image's MIME type must
/// hold a '/' (assimp reads the subtype after it unchecked), and a LINE_LOOP primitive is refused
/// (assimp 5.2 dereferences a null face converting one). All four were found by
/// fuzz/gltf_reader_fuzzer.cpp.
///
/// Errors, one line each: a file past `limits.max_file_bytes` is refused before assimp reads it; the
/// vertex and triangle limits are checked on the imported scene before anything is converted;
/// assimp's own error is `<path>: <first line of assimp's message>`; assimp dropping faces whose
/// indices are out of range (it only warns) is an error; a scene without triangles is an error; a
/// non-finite position, normal, UV or tangent is an error naming the mesh.

#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/result.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace shatter {

/// Reads the asset at `path` by its extension (case-insensitive): .off and .obj by read_mesh, any
/// extension assimp imports through assimp. An unknown extension is an error naming it.
Result<Mesh> read_asset(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Reads an asset held in memory through assimp, `extension` ("glb", "ply", ...) naming its format
/// and `name` the source in messages. For self-contained formats: a file the asset refers to (a
/// .gltf's .bin) is not found.
Result<Mesh> read_asset_bytes(std::span<const std::uint8_t> bytes, std::string_view extension, const std::string& name,
                              const MeshReadLimits& limits = {});

/// True when read_asset reads files with extension `extension` (".glb" or "glb", any case).
[[nodiscard]] bool is_asset_extension(std::string_view extension);

}  // namespace shatter
