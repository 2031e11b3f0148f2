#pragma once
/// Reading a case file (DESIGN.md section 9, documented key by key in cases/README.md): parse, check
/// every key, apply the defaults. Never throws; every error is one line naming the file and key path.
/// Counts past the limits of harness/limits.h (frames, impacts, planes, grid cells, segments, debris)
/// and a file larger than kMaxCaseFileBytes are errors too.

#include "algorithms/core/result.h"
#include "harness/cases/case.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace shatter {

/// The values allowed in `needs`, in contract order.
inline constexpr std::string_view need_names[] = {"fragments", "bonds", "stress", "colliders", "physics"};

/// Reads and checks the case file at `path`. A relative mesh file is resolved against the file's
/// folder first, then the current directory.
Result<Case> load_case(const std::filesystem::path& path);

/// Error when `name` cannot be a case name: it must be a file name that stays in its folder (not empty,
/// at most kMaxCaseNameBytes, no '/', '\\', "..", control characters or leading '.').
Status check_case_name(const std::string& name);

/// Checks case JSON given as text. `source` names it in errors, gives the default name (its stem)
/// and the folder relative mesh files are resolved against; it need not exist.
Result<Case> parse_case(std::string_view text, const std::filesystem::path& source);

}  // namespace shatter
