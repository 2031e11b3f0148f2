// The dashboard page: one self-contained file whose data element holds the data exactly, with text
// from the store (a case name, a branch) unable to end the element or start a script.

#include "harness/history/dashboard/dashboard_html.h"

#include <catch2/catch.hpp>

using namespace shatter;

namespace {

const std::string kHostile = "</script><script>alert(1)</script>";

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

nlohmann::json hostile_data() {
  return nlohmann::json{
      {"format", 1},
      {"store", "h.sqlite"},
      {"settings", {{"window", 30}, {"max_pvalue", 0.001}, {"min_magnitude", 0}}},
      {"commits", {{{"sha", std::string(40, 'a')}, {"time", 1}, {"branch", kHostile + " & <!-- \u2028"}}}},
      {"series",
       {{{"id", "0000000000000001"}, {"kind", "grid"}, {"case", kHostile}, {"subject", "<img src=x onerror=alert(1)>"},
         {"what", "worst frame"}, {"metric", "cpu_ms"}, {"unit", "ms"}, {"better", "lower"}, {"fingerprint", "f"},
         {"fracturer", "voronoi"}, {"points", {{0, 1.5, 1.0, 2.0, 3}}}, {"changes", nlohmann::json::array()}}}}};
}

}  // namespace

TEST_CASE("dashboard page: hostile store text stays data in one script element", "[history][dashboard]") {
  const nlohmann::json data = hostile_data();
  const std::string page = dashboard_html(data);
  CHECK(page.rfind("<!doctype html>", 0) == 0);
  CHECK(count_of(page, "<!doctype") == 1);
  // The data element and the bundle: no third script, and the hostile text never raw.
  CHECK(count_of(page, "<script") == 2);
  CHECK(count_of(page, "</script>") == 2);
  CHECK(page.find(kHostile) == std::string::npos);
  CHECK(page.find("<img") == std::string::npos);
  CHECK(page.find("default-src 'none'") != std::string::npos);
  // Nothing is loaded: no element or rule of the page's own names a file or a URL.
  for (const char* loads : {"<link", "<iframe", "<script src", "@import", "url(http", "url(//"}) {
    INFO(loads);
    CHECK(page.find(loads) == std::string::npos);
  }
  // The data element parses back to exactly the data.
  const std::string open = "<script type=\"application/json\" id=\"" + std::string(kDashboardDataElementId) + "\">";
  const std::size_t begin = page.find(open);
  REQUIRE(begin != std::string::npos);
  const std::size_t end = page.find("</script>", begin);
  REQUIRE(end != std::string::npos);
  const std::string text = page.substr(begin + open.size(), end - begin - open.size());
  CHECK(text.find('<') == std::string::npos);
  CHECK(nlohmann::json::parse(text) == data);
  // The data comes before the script that reads it.
  CHECK(begin < page.find("<script>\n"));
}

TEST_CASE("dashboard page: a branch that is not UTF-8 is replaced, not thrown", "[history][dashboard]") {
  nlohmann::json data = hostile_data();
  data["commits"][0]["branch"] = std::string("feature-\xff\xfe");
  std::string page;
  REQUIRE_NOTHROW(page = dashboard_html(data));
  CHECK(page.find("feature-\xef\xbf\xbd") != std::string::npos);  // U+FFFD
}
