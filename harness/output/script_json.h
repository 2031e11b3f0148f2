#pragma once
/// JSON text made safe to sit inside an HTML `<script type="application/json">` element.

#include <string>
#include <string_view>

namespace shatter {

/// `json` (valid JSON text, UTF-8) with every `<`, `>` and `&` written as `\u003c`, `\u003e`, `\u0026` and
/// the line separators U+2028 and U+2029 as `\u2028`, `\u2029`. Those characters can only occur inside
/// JSON strings, where the escapes mean the same characters, so the value parses the same; and without
/// a `<` no text from a results file (a case named `</script><script>...`) can end the element, open a
/// comment or start another tag (docs/report.md, "Escaping").
std::string json_for_script_element(std::string_view json);

}  // namespace shatter
