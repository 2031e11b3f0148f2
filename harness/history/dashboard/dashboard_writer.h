#pragma once
/// Writing the history dashboard's folder: DIR/dashboard.html, whole or not at all.

#include "algorithms/core/result.h"

#include <filesystem>
#include <string_view>

namespace shatter {

/// The page's file name inside the output folder.
inline constexpr std::string_view kDashboardFileName = "dashboard.html";

/// Writes `page` as `dir`/dashboard.html: built in a fresh staging folder beside `dir` and swapped into
/// place (harness/output/output_folder.h: `dir` must be absent, empty or an earlier shatterbench
/// output, and its parent must exist); on any error nothing at `dir` changes.
Status write_dashboard(std::string_view page, const std::filesystem::path& dir);

}  // namespace shatter
