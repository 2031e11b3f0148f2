#pragma once
/// Writing a whole report folder: images, their data and scripts, report.md and report.html, all or nothing.

#include "algorithms/core/result.h"
#include "harness/report/report_inputs.h"

#include <filesystem>
#include <optional>
#include <utility>

namespace shatter {

/// Which grid cell the stage bars show: (pre-fracture, runtime); empty: the largest cell of each grid
/// (largest pre-fracture count, then largest runtime count).
using ChosenCell = std::optional<std::pair<int, int>>;

/// Writes the report of `inputs` into `dir`: per grid file `grid-CASE.png` (heat map) and
/// `stages-CASE.png` (stage bars of the chosen cell), per accuracy file `pareto-FAMILY-CASE.png` per
/// family and case with an error, each with its `.dat` and `.gp`, `report.md`, and `report.html` (the
/// interactive page of every file, stability and table results included: html/report_html.h). Everything is
/// written into a fresh staging folder beside `dir` and swapped into place at the end
/// (harness/output/output_folder.h: `dir` must be absent, empty or an earlier shatterbench output); on
/// any error (gnuplot missing or failing, a chosen cell absent from a grid) nothing at
/// `dir` changes and the temporary folder is removed.
Status write_report(const ReportInputs& inputs, const std::filesystem::path& dir, const ChosenCell& cell);

}  // namespace shatter
