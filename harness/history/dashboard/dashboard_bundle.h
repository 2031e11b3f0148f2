#pragma once
/// The dashboard page's script and style sheet: web/src/dashboard bundled by esbuild at build time and
/// compiled in (cmake/report_page.cmake writes the definitions into the build folder; docs/dashboard.md).

#include <string_view>

namespace shatter {

/// The page's script: a minified IIFE of web/src/dashboard/main.js and uPlot, ASCII, holding no `</script`.
std::string_view dashboard_script();

/// The page's style sheet: uPlot's and web/src/dashboard/dashboard.css, ASCII, holding no `</style`.
std::string_view dashboard_style();

/// The licences of the npm packages the script bundles ("<name> <version>:" then the licence text),
/// ASCII, holding no `--` (the page writes them into an HTML comment).
std::string_view dashboard_licenses();

}  // namespace shatter
