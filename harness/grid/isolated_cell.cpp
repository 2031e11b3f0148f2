#include "harness/grid/isolated_cell.h"

#include "harness/results/grid_reader.h"
#include "harness/process/isolated_run.h"
#include "harness/results/grid_json_reporter.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <exception>
#include <string>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

GridCell failed_cell(const GridCell& settings, std::string reason) { return failed_grid_cell(settings, std::move(reason)); }

}  // namespace

GridCell failed_grid_cell(const GridCell& settings, std::string reason) {
  GridCell cell = settings;
  cell.samples.clear();
  cell.within_budget = false;
  cell.within_latency_budget = false;
  cell.failed = std::move(reason);
  return cell;
}

Result<GridCell> run_cell_isolated(const std::function<Result<GridCell>()>& run, const GridCell& settings,
                                   double timeout_s, double latency_budget_ms) {
  const IsolatedRun child = run_isolated(
      [&] {
        // An exception out of the cell (a plugin's) fails it with the same reason as in the process.
        Result<GridCell> cell = Error{""};
        try {
          cell = run();
        } catch (const std::exception& e) {
          cell = failed_cell(settings, std::string("threw: ") + e.what());
        } catch (...) {
          cell = failed_cell(settings, "threw a non-standard exception");
        }
        const Json out = cell ? Json{{"cell", grid_cell_to_json(*cell)}} : Json{{"error", cell.error().message}};
        return out.dump();
      },
      timeout_s);
  if (child.end == IsolatedRun::End::timed_out)
    return failed_cell(settings, fmt::format("timeout after {:g} s", timeout_s));
  if (child.end == IsolatedRun::End::crashed) return failed_cell(settings, "crashed: " + child.detail);
  const Json answer = Json::parse(child.output, nullptr, false);
  if (answer.is_discarded() || !answer.is_object())
    return failed_cell(settings, "crashed: the child's result is not JSON");
  if (const auto error = answer.find("error"); error != answer.end() && error->is_string())
    return Error{error->get<std::string>()};
  const auto cell = answer.find("cell");
  if (cell == answer.end()) return failed_cell(settings, "crashed: the child's result holds no cell");
  Result<GridCell> back = grid_cell_from_json(
      *cell, fmt::format("cell {} x {}", settings.prefracture, settings.runtime), latency_budget_ms);
  if (!back) return failed_cell(settings, "crashed: the child's result does not read back: " + back.error().message);
  return back;
}

}  // namespace shatter
