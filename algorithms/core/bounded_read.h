#pragma once
/// Reading a whole file into memory under a size limit: the one way shatterbench reads an input file
/// (meshes, case files, results files, instruction dumps). The limit holds before the text is held in
/// memory, whatever the file is: a regular file is refused on its size before anything is read; a
/// pipe or a file that grows while it is read is refused as soon as the bytes read pass the limit;
/// anything else (a directory, a device such as /dev/zero, a socket) is refused without reading.

#include "algorithms/core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace shatter {

/// The whole content of `path` (symbolic links followed), or an error naming the file, `what` it is
/// (for example "mesh file") and the limit: not a regular file or a pipe, more than `max_bytes`
/// bytes, or a failed open or read.
Result<std::string> read_file_bounded(const std::filesystem::path& path, std::uint64_t max_bytes,
                                      std::string_view what);

}  // namespace shatter
