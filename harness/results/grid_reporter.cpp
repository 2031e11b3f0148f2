#include "harness/results/grid_reporter.h"

#include "harness/results/gbench_reporter.h"
#include "harness/results/grid_csv_reporter.h"
#include "harness/results/grid_json_reporter.h"
#include "harness/results/grid_junit_reporter.h"
#include "harness/results/grid_markdown_reporter.h"

namespace shatter {

std::unique_ptr<GridReporter> make_grid_reporter(std::string_view format) {
  if (format == "json") return std::make_unique<JsonGridReporter>();
  if (format == "csv") return std::make_unique<CsvGridReporter>();
  if (format == "gbench") return std::make_unique<GbenchGridReporter>();
  if (format == "gbench-aggregates") return std::make_unique<GbenchGridReporter>(true);
  if (format == "junit") return std::make_unique<JunitGridReporter>();
  if (format == "markdown") return std::make_unique<MarkdownGridReporter>();
  if (format == "instructions-markdown")
    return std::make_unique<MarkdownGridReporter>(MarkdownGridReporter::Table::instructions);
  return nullptr;
}

}  // namespace shatter
