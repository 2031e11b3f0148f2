#pragma once
/// Third-party importers run where their faults cannot take the process down (docs/cli.md, "Formats").
///
/// Design note: assimp parses dozens of formats with code that crashes, asserts or allocates without
/// bound on hostile files (a mutated PLY, a COLLADA file of deeply nested nodes, a zip bomb). The
/// import therefore runs in a forked child with limits on its address space, its time, the files it
/// may write (none) and its core dumps, reads through the confinement of confined_io_system.h, and
/// hands the mesh back in the checked binary form of mesh_codec.h; the parent decodes and checks it.
/// Whatever the child does (a signal, an abort, a limit reached, a damaged answer) is one line naming
/// the file. OFF and OBJ are read by the project's own bounded readers, in the process.

#include "algorithms/core/mesh.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/result.h"

#include <cstdint>
#include <filesystem>

namespace shatter {

/// Limits of one import in a child.
struct ImportLimits {
  std::uint64_t memory_bytes = 0;  ///< address space of the child, bytes; 0: kMaxImportMemoryBytes
  double time_s = 0.0;             ///< wall time, seconds; 0: kMaxImportSeconds
};

/// read_asset(path, limits), with assimp's formats read in a child under `import` (OFF and OBJ in the
/// process). Errors as read_asset's, and one line naming the file when the child crashes, aborts,
/// passes a limit or hands back a mesh that fails the checks of mesh_codec.h.
Result<Mesh> read_asset_isolated(const std::filesystem::path& path, const MeshReadLimits& limits = {},
                                 const ImportLimits& import = {});

}  // namespace shatter
