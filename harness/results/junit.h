#pragma once
/// JUnit XML in the form of Ant's JUnit report, which CI systems read (testsuites > testsuite >
/// properties, testcase, system-out, system-err; a failure element per failed case), for the budget
/// gate of `grid` and the regression gate of `compare`. The output is valid against the schema of
/// that format (tests/fixtures/junit/junit.xsd, written from its documented structure): properties
/// belong to a suite, so per-case figures are suite properties named after their case.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shatter {

/// One test case.
struct JunitCase {
  std::string name;                    ///< e.g. "cell 100 x 25" (unique within its suite)
  std::string classname;               ///< e.g. "shatterbench.grid.building"
  double time_s = 0.0;                 ///< the time the test took, s
  std::optional<std::string> failure;  ///< one-line message of the failure, when it failed
  std::string failure_type;            ///< what kind of failure ("budget", "check", ...); empty: "failure"
  std::string failure_detail;          ///< more than the message (the failure element's text); empty: none
  /// (name, value) of the case's figures: written as suite properties "<case name>: <name>".
  std::vector<std::pair<std::string, std::string>> properties;
};

/// One suite of cases.
struct JunitSuite {
  std::string name;
  std::vector<JunitCase> cases;
  std::string timestamp;  ///< when the suite ran, ISO 8601 without a zone (UTC); empty: omitted
  std::string hostname;   ///< where it ran; empty: "localhost"
  std::vector<std::pair<std::string, std::string>> properties;  ///< the run's (commit, fingerprint, ...)
};

/// The XML document of `suites` (UTF-8, attributes and text escaped).
std::string junit_xml(const std::vector<JunitSuite>& suites);

/// `iso_utc` ("2026-11-22T06:31:56Z") as a JUnit timestamp (the zone dropped); empty when it is not one.
std::string junit_timestamp(const std::string& iso_utc);

}  // namespace shatter
