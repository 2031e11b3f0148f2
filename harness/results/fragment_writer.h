#pragma once
/// Writing fragments to a folder without ever leaving a partial result behind.

#include "algorithms/core/result.h"
#include "algorithms/fracture/fracturer.h"

#include <filesystem>
#include <span>

namespace shatter {

/// Writes `DIR/fragment_NNN.obj` (NNN from 000, at least three digits). The files are written into a
/// fresh temporary folder beside DIR first; only when all are written are they moved in, after the
/// fragment files of an earlier run in DIR are removed. On error nothing in DIR changes.
Status write_fragments(const std::filesystem::path& dir, std::span<const Fragment> fragments);

}  // namespace shatter
