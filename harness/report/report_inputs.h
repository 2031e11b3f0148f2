#pragma once
/// The results files `shatterbench report` reads: grid results (docs/results.md, "Grid results JSON")
/// and accuracy results ("Accuracy results JSON"), checked key by key.

#include "algorithms/core/result.h"
#include "harness/accuracy/accuracy_point.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace shatter {

/// The per-stage times of one run or one cell, ms, in file order.
using StageTimes = std::vector<std::pair<std::string, double>>;

/// One grid cell, as far as the report needs it.
struct ReportCell {
  int prefracture = 0;        ///< requested pre-fracture count
  int runtime = 0;            ///< requested runtime count
  std::string fracturer;      ///< runtime fracturer name ("" when absent)
  std::string stress;         ///< stress model name ("" when absent)
  double worst_frame_ms = 0;  ///< the gated figure, ms
  bool within_budget = true;  ///< worst_frame_ms <= budget_ms
  StageTimes stages_ms;       ///< median per stage, summed over the frames, ms
  std::vector<StageTimes> sample_stages_ms;  ///< the same per repetition (empty when the file has no samples)
  std::string failed;                        ///< why the cell has no figures (`grid --timeout`); empty when it ran
};

/// One grid results file.
struct ReportGrid {
  std::string file;            ///< path as given
  std::string case_name;       ///< case.name
  double budget_ms = 0.0;      ///< budget_ms
  int frames = 0;              ///< frames per run (0 when absent)
  std::vector<ReportCell> cells;  ///< as in the file
};

/// One accuracy results file.
struct ReportAccuracy {
  std::string file;                    ///< path as given
  std::vector<AccuracyPoint> points;   ///< as in the file (time_ms NaN when null)
};

/// Everything the report shows.
struct ReportInputs {
  std::vector<ReportGrid> grids;
  std::vector<ReportAccuracy> accuracies;
};

/// Reads every file; a grid file has `cells`, an accuracy file `kind` "accuracy" and `points`. Errors
/// name the file and, for a missing or mistyped key, the key path ("b.json: cells[2].worst_frame_ms:
/// expected a number").
Result<ReportInputs> read_report_inputs(std::span<const std::string> files);

}  // namespace shatter
