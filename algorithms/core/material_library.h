#pragma once
/// Reading and writing Wavefront material libraries (.mtl), the materials an OBJ file names with
/// `mtllib` and `usemtl`. Only what MaterialSlot holds is read: `newmtl NAME` starts a material, `Kd r g
/// b` is its base colour (one number is a grey), `d a` its alpha and `Tr t` its transparency (alpha =
/// 1 - t; the later of the two wins), `map_Kd [options] FILE` its base colour texture (after options the
/// last token is the file, without them the rest of the line; a path relative to the .mtl's folder). Every other statement (Ka, Ks, Ns, illum, map_Bump,
/// PBR extensions, ...) is skipped. Colours and alpha outside [0, 1] are clamped to it (some exporters
/// write Kd 1.0001). A number that is not a finite double, a statement before the first `newmtl`, or
/// a `newmtl` without a name is an error naming the file and line; a name defined twice keeps its
/// later definition, as renderers do.

#include "algorithms/core/mesh_attributes.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/result.h"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace shatter {

/// The materials of a .mtl file in the order they are defined; texture paths as written (relative to
/// the .mtl's folder). The file is held to `limits.max_file_bytes`.
Result<std::vector<MaterialSlot>> read_mtl(const std::filesystem::path& path, const MeshReadLimits& limits = {});

/// Writes `slots` as a .mtl file: per slot `newmtl`, `Kd`, `d` and `map_Kd` when the slot names a
/// texture file (an embedded image has no file and is not written). Numbers with 17 significant
/// digits, so read_mtl gives the same values back.
Status write_mtl(std::span<const MaterialSlot> slots, const std::filesystem::path& path);

}  // namespace shatter
