#pragma once
/// Writing fragments to a folder without ever leaving a partial result behind.

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <filesystem>
#include <span>

namespace shatter {

/// Writes the folder `DIR` holding `fragment_NNN.obj` (NNN from 000, at least three digits) and, when
/// the fragments carry material slots, the one library `fragments.mtl` they all name, and
/// `fragments.glb` (write_fragments_glb.h: every fragment as a node at its centroid, with its
/// attributes and materials; written for fragments with or without attributes); whole or
/// not at all (harness/output/output_folder.h): DIR must be absent, empty or an earlier output of
/// shatterbench, which is replaced as a whole. On error nothing in DIR changes.
Status write_fragments(const std::filesystem::path& dir, std::span<const Fragment> fragments);

}  // namespace shatter
