#pragma once
/// Stacked bars of one grid cell's time per stage (stages_ms): the median and each repetition.

#include "algorithms/core/result.h"
#include "harness/report/report_inputs.h"

#include <filesystem>
#include <string>

namespace shatter {

/// Writes `STEM.dat`, `STEM.gp` and `STEM.png` into `folder`: one bar for the cell's median stage
/// times and one per repetition (from `samples`), each stacked by stage in file order; stages with no
/// time in any bar are left out. `frames` (0: unknown) goes into the title, since the stage times are
/// summed over the frames. Returns the image's file name.
Result<std::string> plot_stage_bars(const ReportCell& cell, const std::string& case_name, int frames,
                                    const std::filesystem::path& folder, const std::string& stem);

}  // namespace shatter
