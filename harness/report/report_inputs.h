#pragma once
/// The results files `shatterbench report` reads: grid results (docs/results.md, "Grid results JSON"),
/// accuracy results ("Accuracy results JSON"), table results ("Table results JSON") and stability
/// results (docs/cli.md, "stability"), checked key by key; each file's whole document is kept for the
/// HTML page.

#include "algorithms/core/result.h"
#include "harness/accuracy/accuracy_point.h"
#include "harness/report/fragments_folder.h"
#include "harness/stability/hazard_outcome.h"

#include <optional>
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
  nlohmann::ordered_json document;  ///< the whole file as read
  std::string case_name;       ///< case.name
  double budget_ms = 0.0;      ///< budget_ms
  int frames = 0;              ///< frames per run (0 when absent)
  std::vector<ReportCell> cells;  ///< as in the file
  /// The bytes of the recorded frames the file names (`recorded_frames.path`, `grid --record-frames`),
  /// checked whole (recorded_frames.h); empty when it names none.
  std::string recorded_frames;
};

/// One accuracy results file.
struct ReportAccuracy {
  std::string file;                    ///< path as given
  nlohmann::ordered_json document;     ///< the whole file as read
  std::vector<AccuracyPoint> points;   ///< as in the file (time_ms NaN when null)
};

/// One stability results file (`stability --json`).
struct ReportStability {
  std::string file;                    ///< path as given
  nlohmann::ordered_json document;     ///< the whole file as read
  std::vector<HazardResult> results;   ///< one verdict per entry of `results`
};

/// One row of a table results file, as far as the Markdown page needs it.
struct ReportTableRow {
  std::string mesh;          ///< mesh file name
  std::string algorithm;     ///< fracturer name
  int fragments = 0;         ///< requested fragments
  std::string outcome;       ///< "25 fragments", "refused: <message>" or "failed: <message>"
  std::optional<double> time_ms;  ///< median time, ms; empty for a refused or failed row
};

/// One table results file (`table --json`).
struct ReportTable {
  std::string file;                    ///< path as given
  nlohmann::ordered_json document;     ///< the whole file as read
  std::vector<ReportTableRow> rows;    ///< as in the file
};

/// Everything the report shows, each kind in the order the files were given.
struct ReportInputs {
  std::vector<ReportGrid> grids;            ///< grid results
  std::vector<ReportAccuracy> accuracies;   ///< accuracy results
  std::vector<ReportStability> stabilities; ///< stability results
  std::vector<ReportTable> tables;          ///< table results
  std::vector<ReportFragments> fragments;   ///< fragments folders (fracture --out, table --out)
};

/// The schema version of results files this build reads.
inline constexpr int kReportSchemaVersion = 1;

/// Reads every file; a folder is read as fragments folders (find_fragments_folders), and together they
/// may hold at most kMaxReportFragments fragments and kMaxReportTriangles triangles. A grid file has `cells`, a table file `kind` "table" and `rows`, an accuracy file
/// `kind` "accuracy" and `points`, a stability file `results`. A `schema_version` other than
/// kReportSchemaVersion is refused. A grid file's recorded frames are read from its own folder (at most
/// kMaxReportRecordingBytes over the report). Errors name the file and, for a missing or mistyped key, the key
/// path ("b.json: cells[2].worst_frame_ms: expected a number").
Result<ReportInputs> read_report_inputs(std::span<const std::string> files);

}  // namespace shatter
