#pragma once
/// Writing a file so that readers see either the old content or the new, never a partial file.

#include "algorithms/core/result.h"

#include <filesystem>
#include <string_view>

namespace shatter {

/// A fresh name for a temporary sibling of `path`: `.NAME.partial-` plus 8 random hex digits in the same folder (a
/// rename within one folder is one step). Nothing is created.
std::filesystem::path temporary_beside(const std::filesystem::path& path);

/// Writes `content` (bytes, as given) to `path`. The bytes go to a fresh temporary file in the same
/// folder (`.NAME.partial-` plus 8 random hex digits), which is flushed to disk (fsync) and then renamed over `path`; a
/// rename within one folder replaces the target in one step. On any error nothing at `path` changes,
/// the temporary is removed and the message names `path`. The folder must exist; a replaced file takes
/// the default permissions (0666 less the umask), not the old file's.
Status write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace shatter
