#pragma once
/// The files an asset refers to (an OBJ's `mtllib`, an MTL's `map_Kd`, a glTF's buffers and images)
/// stay inside the asset's own folder (docs/cli.md, "Formats": references).
///
/// Design note: an asset file is untrusted input, and so is every path written inside it. A reference
/// is taken only as a relative path whose components are plain names (no `..`, no root, no URI scheme
/// or drive), and a referenced file is read only when, with every symbolic link followed, it is a
/// regular file inside the folder of the asset and within the size limit. So no asset can make the
/// tool read `/etc/shadow`, `/proc/self/mem`, a device or a FIFO, or carry such a path into the
/// fragments it writes.

#include "algorithms/core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace shatter {

/// Error unless `reference` is a relative path of plain names: not empty, no NUL or control
/// character, no root (`/x`, `\x`), no drive or URI scheme (`c:`, `file:`), no `..` component, and no
/// `\` separator. `what` names the kind of reference in the message ("material library").
Status check_reference_text(std::string_view reference, std::string_view what);

/// The file `reference` names in `folder` (the asset's own folder), after check_reference_text: Error
/// unless it exists, is a regular file with every link followed, lies inside `folder` once both are
/// made canonical, and holds at most `max_bytes` bytes. The message names the reference and why.
Result<std::filesystem::path> resolve_reference(const std::filesystem::path& folder, std::string_view reference,
                                                std::uint64_t max_bytes, std::string_view what);

/// True when `path` (canonical) is `folder` (canonical) or lies inside it.
bool path_inside(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace shatter
