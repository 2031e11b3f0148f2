#pragma once
/// Writing a folder of files (fragments, a report) so that it is replaced whole or not at all.
///
/// The new folder is built beside the target (`.NAME.partial-XXXXXXXX`, marked with kOutputMarker
/// from its first moment), then swapped in with one rename (renameat2 RENAME_EXCHANGE when the target
/// exists); the old content stays intact until the swap and is removed after it. Only a folder that
/// is absent, empty or marked as shatterbench's own is replaced: anything else is refused, never
/// emptied (check_outputs() says so before a command runs; this checks again under the lock).

#include "algorithms/core/result.h"

#include <filesystem>
#include <functional>

namespace shatter {

/// Fills a staging folder; an error abandons the whole output.
using FolderFiller = std::function<Status(const std::filesystem::path& staging)>;

/// Error when `dir` may not be replaced by a shatterbench output: it is not a folder, or it is a
/// non-empty folder without kOutputMarker. `flag` names the option in the message.
Status check_replaceable_folder(const std::filesystem::path& dir, std::string_view flag);

/// Builds the folder `dir` with `fill` and swaps it in, holding the lock of `dir`'s parent folder
/// (which must exist). On any error `dir` is as it was and nothing of the new folder is left.
Status write_folder_atomically(const std::filesystem::path& dir, const FolderFiller& fill);

}  // namespace shatter
