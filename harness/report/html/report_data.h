#pragma once
/// The data the report page draws: the results files as read, in one JSON document.

#include "harness/report/report_inputs.h"

#include <string>

namespace shatter {

/// The page's data as compact JSON text: `{"format": 1, "grids": [...], "accuracy": [...], "stability":
/// [...], "tables": [...], "fragments": [...]}`, each results entry `{"file": path as given, "results":
/// the file's document}` (a grid with recorded frames also `"recorded_frames"`: the sidecar's bytes
/// gzip-compressed, in base64), each fragments entry its folder, labels, summary, glTF binary
/// (gzip-compressed, in base64) and images as
/// data: URLs (docs/report.md, "The data"). Not yet escaped for a script element (json_for_script_element).
std::string report_data_json(const ReportInputs& inputs);

}  // namespace shatter
