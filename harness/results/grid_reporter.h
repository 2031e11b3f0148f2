#pragma once
/// Every output format of a grid's results is a reporter behind one interface, as Google Benchmark's
/// reporters are: the results JSON and its CSV twin, Google Benchmark's JSON, JUnit XML and the
/// Markdown table. Each writes the typed timings its format has always held and every named figure
/// (figure_record.h) whose spec asks for that format, with no code of its own for any one figure.

#include "harness/results/grid_record.h"
#include "harness/results/run_context.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace shatter {

/// What a reporter reports: the grid, the case it ran and the context it ran in.
struct GridReport {
  const GridResult& grid;                  ///< the cells and their figures
  std::string case_name;                   ///< the case's name
  nlohmann::ordered_json case_block;       ///< the results JSON's `case` block (case_to_json)
  RunContext context;                      ///< where and how it ran
  /// The results JSON's `input` block (input_solid_json): the solid and its repairs; null leaves it out.
  nlohmann::ordered_json input_block = nullptr;
};

/// One output format of a grid's results.
class GridReporter {
 public:
  virtual ~GridReporter() = default;
  /// The format's name: "json", "csv", "gbench", "junit" or "markdown".
  [[nodiscard]] virtual std::string_view format() const = 0;
  /// The whole document of `report` in this format (text, ending in a line break).
  [[nodiscard]] virtual std::string render(const GridReport& report) const = 0;
};

/// The reporter of `format` ("json", "csv", "gbench", "junit", "markdown", "instructions-markdown"),
/// or null for a name it does not know.
std::unique_ptr<GridReporter> make_grid_reporter(std::string_view format);

}  // namespace shatter
