#pragma once
/// Writing files so that readers see either the old content or the new, never a partial file.
///
/// A file is written as an unnamed file in its target's folder (O_TMPFILE), flushed to disk (fsync),
/// then given a temporary name beside the target (`.NAME.partial-` plus 8 random hex digits, taken
/// only if free) and renamed over it, with the lock of its folder held (folder_lock.h). A run killed
/// while writing leaves nothing; an interrupt (SIGINT, SIGTERM, SIGHUP) removes the named temporary
/// of the short step between naming and renaming (harness/signals/interrupt_cleanup.h). Where the
/// file system has no unnamed files, a named temporary is written instead. A file whose name looks
/// like a temporary is never removed: it may be the user's.

#include "algorithms/core/result.h"

#include <filesystem>
#include <span>
#include <string_view>

namespace shatter {

/// The file that marks a folder as written (and so replaceable) by shatterbench.
inline constexpr std::string_view kOutputMarker = ".shatterbench-output";

/// A fresh name for a temporary sibling of `path`: `.NAME.partial-` plus 8 random hex digits in the
/// same folder (a rename within one folder is one step). Nothing is created.
std::filesystem::path temporary_beside(const std::filesystem::path& path);

/// Removes what killed runs left beside `path`: staging folders named `.NAME.partial-XXXXXXXX` that
/// hold kOutputMarker (files and other folders of such names are left alone). Call with the folder's
/// lock held.
void remove_stale_temporaries(const std::filesystem::path& path);

/// One file of an output set: where it goes and its bytes (as given).
struct FileContent {
  std::filesystem::path path;
  std::string_view content;
};

/// Writes every file of `files` as one set: the folders' locks are taken, every file is written to
/// its temporary and flushed, and only then are they renamed into place, in order. An existing target
/// that is not a regular file (a folder, device, FIFO or socket) is refused; a symbolic link is kept
/// and the file it names is replaced. On any error before the renames nothing at the targets changes,
/// the temporaries are removed and the message names the path. The folders must exist; a replaced
/// file takes the default permissions (0666 less the umask), not the old file's.
Status write_files_atomically(std::span<const FileContent> files);

/// Writes one file as write_files_atomically() does.
Status write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace shatter
