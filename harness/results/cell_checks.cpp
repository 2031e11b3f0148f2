#include "harness/results/cell_checks.h"

#include "harness/metrics/fracture_acceptance.h"

#include <fmt/core.h>

namespace shatter {

std::vector<std::string> failed_cell_checks(const GridCell& cell) {
  std::vector<std::string> failed;
  if (!cell.failed.empty()) return failed;
  const FractureAcceptance acceptance;
  const CellAccuracy& e = cell.accuracy;
  const auto check = [&](const char* stage, bool all_closed, double volume_error, double partition_error) {
    // Negated comparisons: a NaN figure fails too.
    if (!all_closed) failed.push_back(fmt::format("{}: all_closed: a fragment is not a valid solid", stage));
    if (!(volume_error <= acceptance.max_volume_error))
      failed.push_back(fmt::format("{}: volume_error {:.6g} > {:g}", stage, volume_error, acceptance.max_volume_error));
    if (!(partition_error <= acceptance.max_partition_error))
      failed.push_back(
          fmt::format("{}: partition_error {:.6g} > {:g}", stage, partition_error, acceptance.max_partition_error));
  };
  check("pre-fracture", e.prefracture_all_closed, e.prefracture_volume_error, e.prefracture_partition_error);
  check("runtime", e.runtime_all_closed, e.runtime_volume_error, e.runtime_partition_error);
  return failed;
}

}  // namespace shatter
