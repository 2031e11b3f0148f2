#include "harness/output/html_page.h"

namespace shatter {

std::string html_page(const HtmlPageParts& parts) {
  std::string page;
  page.reserve(parts.data.size() + parts.script.size() + parts.style.size() + parts.licenses.size() + 1024);
  page += "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  // Inline script and style only; nothing may be fetched from anywhere but the page itself: a 3D view
  // decodes its embedded glTF binaries and textures from data: and blob: URLs.
  page += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
          "style-src 'unsafe-inline'; img-src data: blob:; connect-src data: blob:\">\n";
  page += "<title>";
  page += parts.title;
  page += "</title>\n<!--\nThe script of this page bundles these packages, under these licences:\n\n";
  page += parts.licenses;
  page += "-->\n<style>\n";
  page += parts.style;
  page += "\n</style>\n</head>\n<body>\n<main id=\"";
  page += parts.root_id;
  page += "\"></main>\n<script type=\"application/json\" id=\"";
  page += parts.data_id;
  page += "\">";
  page += parts.data;
  page += "</script>\n<script>\n";
  page += parts.script;
  page += "\n</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace shatter
