#include "harness/results/junit.h"

#include <fmt/core.h>

#include <cctype>

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

void append_property(std::string& out, const std::string& name, const std::string& value) {
  out += fmt::format("      <property name=\"{}\" value=\"{}\"/>\n", escape(name), escape(value));
}

}  // namespace

std::string junit_timestamp(const std::string& iso_utc) {
  // YYYY-MM-DDTHH:MM:SS, then an optional fraction and zone, which are dropped.
  if (iso_utc.size() < 19) return {};
  const std::string head = iso_utc.substr(0, 19);
  for (std::size_t i = 0; i < head.size(); ++i) {
    const char expected = i == 4 || i == 7 ? '-' : i == 10 ? 'T' : i == 13 || i == 16 ? ':' : '0';
    if (expected == '0' ? !std::isdigit(static_cast<unsigned char>(head[i])) : head[i] != expected) return {};
  }
  return head;
}

std::string junit_xml(const std::vector<JunitSuite>& suites) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  // No attributes on the root: Ant's schema allows none there (the counts are each suite's).
  out += "<testsuites>\n";
  int id = 0;
  for (const JunitSuite& s : suites) {
    int suite_failures = 0;
    double time = 0.0;
    for (const JunitCase& c : s.cases) {
      suite_failures += c.failure ? 1 : 0;
      time += c.time_s;
    }
    // The package is the name up to its last dot ("shatterbench.grid" of "shatterbench.grid.building").
    const std::size_t dot = s.name.rfind('.');
    const std::string package = dot == std::string::npos ? s.name : s.name.substr(0, dot);
    out += fmt::format("  <testsuite name=\"{}\" package=\"{}\" id=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" "
                       "skipped=\"0\" time=\"{:.6f}\" hostname=\"{}\"",
                       escape(s.name), escape(package), id++, s.cases.size(), suite_failures, time,
                       escape(s.hostname.empty() ? std::string("localhost") : s.hostname));
    if (!s.timestamp.empty()) out += fmt::format(" timestamp=\"{}\"", escape(s.timestamp));
    out += ">\n    <properties>\n";
    for (const auto& [name, value] : s.properties) append_property(out, name, value);
    for (const JunitCase& c : s.cases)
      for (const auto& [name, value] : c.properties) append_property(out, c.name + ": " + name, value);
    out += "    </properties>\n";
    for (const JunitCase& c : s.cases) {
      out += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\"", escape(c.name),
                         escape(c.classname), c.time_s);
      if (!c.failure) {
        out += "/>\n";
        continue;
      }
      const std::string type = c.failure_type.empty() ? std::string("failure") : c.failure_type;
      out += fmt::format(">\n      <failure message=\"{}\" type=\"{}\"", escape(*c.failure), escape(type));
      out += c.failure_detail.empty() ? "/>\n" : fmt::format(">{}</failure>\n", escape(c.failure_detail));
      out += "    </testcase>\n";
    }
    out += "    <system-out/>\n    <system-err/>\n  </testsuite>\n";
  }
  out += "</testsuites>\n";
  return out;
}

}  // namespace shatter
