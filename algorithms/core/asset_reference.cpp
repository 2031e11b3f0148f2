#include "algorithms/core/asset_reference.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace shatter {
namespace fs = std::filesystem;

namespace {

/// The reference as shown in a message: at most 200 bytes, control characters as '?'.
std::string shown(std::string_view reference) {
  std::string out;
  for (const char c : reference.substr(0, 200)) out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
  return out + (reference.size() > 200 ? "..." : "");
}

}  // namespace

Status check_reference_text(std::string_view reference, std::string_view what) {
  const std::string refused = std::string(what) + " '" + shown(reference) + "' refused: ";
  if (reference.empty()) return Error{std::string(what) + ": an empty file name"};
  for (const char c : reference)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return Error{refused + "it holds a control character"};
  if (reference.front() == '/' || reference.front() == '\\')
    return Error{refused + "an absolute path (references must be relative to the asset's folder)"};
  if (reference.find('\\') != std::string_view::npos) return Error{refused + "a '\\' separator (use '/')"};
  // A scheme or a drive before the first separator: "file:", "http:", "c:".
  const std::size_t colon = reference.find(':');
  if (colon != std::string_view::npos && colon < reference.find('/'))
    return Error{refused + "a URI scheme or drive (references must be relative file names)"};
  for (const auto& part : fs::path(std::string(reference)))
    if (part == "..") return Error{refused + "it leaves the asset's folder ('..')"};
  return {};
}

bool path_inside(const fs::path& path, const fs::path& folder) {
  const auto [f, p] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return f == folder.end() || (std::next(f) == folder.end() && f->empty());
}

Result<fs::path> resolve_reference(const fs::path& folder, std::string_view reference, std::uint64_t max_bytes,
                                   std::string_view what) {
  if (Status s = check_reference_text(reference, what); !s) return s.error();
  const std::string refused = std::string(what) + " '" + shown(reference) + "' refused: ";
  const fs::path base = folder.empty() ? fs::path(".") : folder;
  const fs::path named = base / std::string(reference);
  std::error_code ec;
  const fs::file_status status = fs::status(named, ec);
  if (!fs::exists(status)) return Error{std::string(what) + " '" + shown(reference) + "' not found (looked for " + named.string() + ")"};
  if (!fs::is_regular_file(status)) return Error{refused + "not a regular file"};
  const fs::path real = fs::canonical(named, ec);
  const fs::path real_folder = fs::canonical(base, ec);
  if (ec || !path_inside(real, real_folder))
    return Error{refused + "a link to " + real.string() + ", outside the asset's folder"};
  const std::uintmax_t size = fs::file_size(real, ec);
  if (ec) return Error{refused + ec.message()};
  if (size > max_bytes)
    return Error{refused + std::to_string(size) + " bytes, past the limit of " + std::to_string(max_bytes) + " bytes"};
  return real;
}

}  // namespace shatter
