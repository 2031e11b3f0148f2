#pragma once
/// The history dashboard's HTML page (dashboard.html): one self-contained file that opens from file://
/// with no network request, its script, style and data inline (docs/dashboard.md).

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace shatter {

/// The id of the `<script type="application/json">` element that holds the dashboard's data.
inline constexpr std::string_view kDashboardDataElementId = "shatterbench-dashboard";

/// The page for `data` (dashboard_data's value): `<!doctype html>`, the bundled style sheet, the data
/// element (escaped by json_for_script_element, invalid UTF-8 replaced) and the bundled script, in that
/// order. The page loads nothing, and its Content-Security-Policy forbids every fetch.
std::string dashboard_html(const nlohmann::json& data);

}  // namespace shatter
