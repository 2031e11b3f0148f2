#pragma once
/// JUnit XML (the structure CI systems read: testsuites > testsuite > testcase, a failure element per
/// failed case), for the budget gate of `grid` and the regression gate of `compare`.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shatter {

/// One test case.
struct JunitCase {
  std::string name;                    ///< e.g. "cell 100 x 25"
  std::string classname;               ///< e.g. "shatterbench.grid.building"
  double time_s = 0.0;                 ///< seconds
  std::optional<std::string> failure;  ///< message of the failure, when it failed
  std::vector<std::pair<std::string, std::string>> properties;  ///< (name, value) of the case's properties
};

/// One suite of cases.
struct JunitSuite {
  std::string name;
  std::vector<JunitCase> cases;
};

/// The XML document of `suites` (UTF-8, attributes and text escaped).
std::string junit_xml(const std::vector<JunitSuite>& suites);

}  // namespace shatter
