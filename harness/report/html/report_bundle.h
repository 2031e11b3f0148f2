#pragma once
/// The report page's script and style sheet: web/src/report bundled by esbuild at build time and compiled
/// in (cmake/report_page.cmake writes the definitions into the build folder; docs/report.md).

#include <string_view>

namespace shatter {

/// The page's script: a minified IIFE of web/src/report/main.js and uPlot, ASCII, holding no `</script`.
std::string_view report_script();

/// The page's style sheet: uPlot's and web/src/report/report.css, ASCII, holding no `</style`.
std::string_view report_style();

/// The licences of the npm packages the script bundles ("<name> <version>:" then the licence text),
/// ASCII, holding no `--` (the page writes them into an HTML comment).
std::string_view report_licenses();

}  // namespace shatter
