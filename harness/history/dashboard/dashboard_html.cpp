#include "harness/history/dashboard/dashboard_html.h"

#include "harness/history/dashboard/dashboard_bundle.h"
#include "harness/report/html/script_json.h"

namespace shatter {

std::string dashboard_html(const nlohmann::json& data) {
  // A branch name is git's bytes: anything not UTF-8 becomes U+FFFD rather than an exception.
  const std::string text =
      json_for_script_element(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  std::string page;
  page.reserve(text.size() + dashboard_script().size() + dashboard_style().size() + 1024);
  page += "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  // Inline script and style only; nothing may be fetched.
  page += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
          "style-src 'unsafe-inline'; img-src data: blob:\">\n";
  page += "<title>shatterbench history</title>\n";
  page += "<!--\nThe script of this page bundles these packages, under these licences:\n\n";
  page += dashboard_licenses();
  page += "-->\n<style>\n";
  page += dashboard_style();
  page += "\n</style>\n</head>\n<body>\n<main id=\"dashboard\"></main>\n";
  page += "<script type=\"application/json\" id=\"";
  page += kDashboardDataElementId;
  page += "\">";
  page += text;
  page += "</script>\n<script>\n";
  page += dashboard_script();
  page += "\n</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace shatter
