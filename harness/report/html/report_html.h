#pragma once
/// The report's HTML page (report.html): one self-contained file that opens from file:// with no network
/// request, its script, style and data inline (docs/report.md).

#include "harness/report/report_inputs.h"

#include <string>
#include <string_view>

namespace shatter {

/// The id of the `<script type="application/json">` element that holds the page's data.
inline constexpr std::string_view kReportDataElementId = "shatterbench-data";

/// The page for `inputs`: `<!doctype html>`, the bundled style sheet, the data element (report_data_json
/// escaped by json_for_script_element) and the bundled script, in that order. The page loads nothing:
/// no `src`, `href` or `url()` of its own names a file or a URL, and its Content-Security-Policy
/// forbids every fetch (`default-src 'none'`), so a page copied anywhere works offline.
std::string report_html(const ReportInputs& inputs);

}  // namespace shatter
