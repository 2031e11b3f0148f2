#pragma once
/// A grid's gates as JUnit XML: one test case per cell, failed when the cell failed, a result check of
/// its fractures failed, or (time mode) it broke the frame or latency budget. Each named figure whose
/// spec asks for JUnit (kFigureInJunit) is a property of its cell's test case.

#include "harness/results/grid_reporter.h"
#include "harness/results/junit.h"

namespace shatter {

/// The JUnit XML of a grid's gates.
class JunitGridReporter final : public GridReporter {
 public:
  /// "junit".
  [[nodiscard]] std::string_view format() const override { return "junit"; }
  /// junit_xml of grid_junit_suite(report).
  [[nodiscard]] std::string render(const GridReport& report) const override;
};

/// The suite `shatterbench.grid.<case>`: one case per cell, its time the cell's worst frame in s.
JunitSuite grid_junit_suite(const GridReport& report);

}  // namespace shatter
