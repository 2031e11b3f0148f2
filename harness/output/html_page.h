#pragma once
/// The shell of shatterbench's self-contained HTML pages (the report, the history dashboard): head,
/// licence comment, inline style, the data element and the inline script, under a Content-Security-
/// Policy that lets the page fetch nothing but its own data: and blob: URLs.

#include <string>
#include <string_view>

namespace shatter {

/// What one page is made of; every text is inserted as it is (the data already escaped by
/// json_for_script_element, the bundle checked at build time).
struct HtmlPageParts {
  std::string_view title;        ///< the <title>
  std::string_view root_id;      ///< id of the <main> element the script draws into
  std::string_view data_id;      ///< id of the <script type="application/json"> data element
  std::string_view data;         ///< the data element's text
  std::string_view script;       ///< the bundled script
  std::string_view style;        ///< the bundled style sheet
  std::string_view licenses;     ///< the bundled packages' licences, for the head comment
};

/// The page: `<!doctype html>`, the licence comment, the style sheet, the data element and the
/// script, in that order.
[[nodiscard]] std::string html_page(const HtmlPageParts& parts);

}  // namespace shatter
