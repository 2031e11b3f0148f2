#pragma once
/// The result checks of a grid cell: its pre-fracture and runtime fractures must be valid results
/// by the same acceptance rule as `fracture` (fracture_acceptance.h).

#include "harness/results/grid_record.h"

#include <string>
#include <vector>

namespace shatter {

/// The checks the worst error figures of `cell` fail, one line each ("runtime: all_closed: a piece
/// is not a valid solid", "pre-fracture: volume_error 0.3 > 1e-06"); empty when every check holds
/// or the cell did not run (a failed cell reports why in `failed`).
std::vector<std::string> failed_cell_checks(const GridCell& cell);

}  // namespace shatter
