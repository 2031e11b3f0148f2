#pragma once
/// Writing fragments as one binary glTF 2.0 file (.glb) that a game engine or viewer opens directly.
///
/// Design note. The file is written here with nlohmann-json and a byte buffer, not with assimp's
/// exporter: tried on this project's assimp (5.2), the "glb2" exporter declares extensions it does not
/// use (KHR_materials_volume, FB_ngon_encoding, which a validator reports), stores node placement as
/// matrices rather than a translation, and needs an aiScene built with raw owning arrays. Written
/// directly, the layout is exactly what is documented here.
///
/// Layout: one node per fragment, named `fragment_NNN` (NNN from 000, as the OBJ files), its
/// `translation` the fragment's centroid (Fragment::mass.centroid) and its mesh's positions relative
/// to it, so every fragment sits where it was and pivots about its centre of mass; its `extras.volume`
/// the fragment's volume (m^3, Fragment::mass.volume). Each mesh has one
/// primitive (triangles, indexed, uint32) per material its faces use; corners with equal position and
/// attributes share a vertex. Accessors (float32, as glTF requires for these): POSITION with min and
/// max; NORMAL, normalised (the flat face normal when the mesh has no normals); TEXCOORD_n per UV set,
/// with v flipped (glTF's v points down, the attributes' v up, see read_asset.h); TANGENT (xyz
/// normalised, w = +1 or -1) when the mesh has tangents. Materials: one per distinct slot name over all
/// fragments, used or not (the interior material always included), in slot order, with pbrMetallicRoughness
/// baseColorFactor, metallicFactor 0, alphaMode BLEND when alpha < 1, and baseColorTexture (TEXCOORD_0)
/// whose image is embedded in the binary chunk when the slot holds its bytes, else referenced by the
/// slot's file path as a relative URI. A fragment without material slots has up to two primitives:
/// its surface (and repair) faces with glTF's default material, its cut faces with material
/// `interior` (a warm red-brown), so a viewer tells the two apart.

#include "algorithms/core/fragment.h"
#include "algorithms/core/result.h"

#include <filesystem>
#include <span>

namespace shatter {

/// Writes `fragments` to `path` as a binary glTF (see the file comment). An error names the file
/// (cannot write) or the fragment (a non-finite value, more than 2^32 - 1 vertices in one primitive).
Status write_fragments_glb(const std::filesystem::path& path, std::span<const Fragment> fragments);

}  // namespace shatter
