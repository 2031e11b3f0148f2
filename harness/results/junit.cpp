#include "harness/results/junit.h"

#include <fmt/core.h>

namespace shatter {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters other than tab and newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') out += ' ';
        else out += c;
    }
  }
  return out;
}

}  // namespace

std::string junit_xml(const std::vector<JunitSuite>& suites) {
  int tests = 0, failures = 0;
  for (const JunitSuite& s : suites)
    for (const JunitCase& c : s.cases) {
      ++tests;
      failures += c.failure ? 1 : 0;
    }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format("<testsuites tests=\"{}\" failures=\"{}\">\n", tests, failures);
  for (const JunitSuite& s : suites) {
    int suite_failures = 0;
    double time = 0.0;
    for (const JunitCase& c : s.cases) {
      suite_failures += c.failure ? 1 : 0;
      time += c.time_s;
    }
    out += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\" time=\"{:.6f}\">\n",
                       escape(s.name), s.cases.size(), suite_failures, time);
    for (const JunitCase& c : s.cases) {
      out += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\"", escape(c.name), escape(c.classname),
                         c.time_s);
      if (!c.failure && c.properties.empty()) {
        out += "/>\n";
        continue;
      }
      out += ">\n";
      if (!c.properties.empty()) {
        out += "      <properties>\n";
        for (const auto& [name, value] : c.properties)
          out += fmt::format("        <property name=\"{}\" value=\"{}\"/>\n", escape(name), escape(value));
        out += "      </properties>\n";
      }
      if (c.failure) out += fmt::format("      <failure message=\"{}\">{}</failure>\n", escape(*c.failure), escape(*c.failure));
      out += "    </testcase>\n";
    }
    out += "  </testsuite>\n";
  }
  out += "</testsuites>\n";
  return out;
}

}  // namespace shatter
