#pragma once
/// gzip (RFC 1952) for the binaries a report page embeds: glTF files and recorded frames shrink to a
/// third or less, and the page inflates them with the browser's own DecompressionStream("gzip").

#include "algorithms/core/result.h"

#include <string>
#include <string_view>

namespace shatter {

/// `bytes` gzip-compressed (zlib, level 6); an error only when zlib fails (out of memory).
[[nodiscard]] Result<std::string> gzip(std::string_view bytes);

}  // namespace shatter
