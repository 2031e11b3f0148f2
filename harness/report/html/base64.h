#pragma once
/// Base64 (RFC 4648, with padding) for the binaries a report page embeds: glTF files, images and
/// recorded frames travel inside the page's JSON as text and are decoded by the page.

#include <string>
#include <string_view>

namespace shatter {

/// `bytes` in base64 with `=` padding, no line breaks.
[[nodiscard]] std::string base64(std::string_view bytes);

}  // namespace shatter
