// json_for_script_element: JSON that no text can turn into markup inside a <script> element.

#include "harness/output/script_json.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace {

using shatter::json_for_script_element;

}  // namespace

TEST_CASE("script json: <, >, & and the line separators are escaped, and the value is unchanged", "[report][html]") {
  const std::string hostile = "</script><script>alert(1)</script> & <!-- \xE2\x80\xA8 \xE2\x80\xA9 caf\xC3\xA9";
  const nlohmann::json value = {{"case", {{"name", hostile}}}, {"n", 1.5}};
  const std::string escaped = json_for_script_element(value.dump());
  CHECK(escaped.find('<') == std::string::npos);
  CHECK(escaped.find('>') == std::string::npos);
  CHECK(escaped.find('&') == std::string::npos);
  CHECK(escaped.find("\xE2\x80\xA8") == std::string::npos);
  CHECK(escaped.find("\xE2\x80\xA9") == std::string::npos);
  CHECK(escaped.find("\\u003c/script\\u003e\\u003cscript\\u003ealert(1)") != std::string::npos);
  CHECK(escaped.find("\\u2028 \\u2029") != std::string::npos);
  CHECK(escaped.find("caf\xC3\xA9") != std::string::npos);  // other text passes as it is
  CHECK(nlohmann::json::parse(escaped) == value);
}

TEST_CASE("script json: a backslash before an escaped character stays a backslash", "[report][html]") {
  const nlohmann::json value = {{"text", "\\<\\>"}};
  const std::string escaped = json_for_script_element(value.dump());
  CHECK(escaped.find('<') == std::string::npos);
  CHECK(nlohmann::json::parse(escaped) == value);
}
