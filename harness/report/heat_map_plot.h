#pragma once
/// The grid heat map: worst_frame_ms per cell against the budget, rows pre-fracture, columns runtime.

#include "algorithms/core/result.h"
#include "harness/report/report_inputs.h"

#include <filesystem>
#include <string>

namespace shatter {

/// Writes `STEM.dat`, `STEM.gp` and the image `STEM.png` into `folder` (gnuplot, pngcairo): one
/// coloured square per cell (green well under the budget, yellow to orange up to it, red over it),
/// its worst frame in ms printed in it, and cells over the budget framed and marked "!". Returns the
/// image's file name.
Result<std::string> plot_heat_map(const ReportGrid& grid, const std::filesystem::path& folder, const std::string& stem);

}  // namespace shatter
