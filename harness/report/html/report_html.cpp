#include "harness/report/html/report_html.h"

#include "harness/report/html/report_bundle.h"
#include "harness/report/html/report_data.h"
#include "harness/report/html/script_json.h"

namespace shatter {

std::string report_html(const ReportInputs& inputs) {
  const std::string data = json_for_script_element(report_data_json(inputs));
  std::string page;
  page.reserve(data.size() + report_script().size() + report_style().size() + 1024);
  page += "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  // Inline script and style only; nothing may be fetched from anywhere but the page itself: the 3D
  // views decode their embedded glTF binaries and textures from data: and blob: URLs.
  page += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
          "style-src 'unsafe-inline'; img-src data: blob:; connect-src data: blob:\">\n";
  page += "<title>shatterbench report</title>\n";
  page += "<!--\nThe script of this page bundles these packages, under these licences:\n\n";
  page += report_licenses();
  page += "-->\n<style>\n";
  page += report_style();
  page += "\n</style>\n</head>\n<body>\n<main id=\"report\"></main>\n";
  page += "<script type=\"application/json\" id=\"";
  page += kReportDataElementId;
  page += "\">";
  page += data;
  page += "</script>\n<script>\n";
  page += report_script();
  page += "\n</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace shatter
