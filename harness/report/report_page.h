#pragma once
/// The Markdown page of a report (report.md): the images and the tables they were drawn from.

#include "harness/report/report_inputs.h"

#include <string>
#include <vector>

namespace shatter {

/// What was drawn for one grid file.
struct GridFigures {
  const ReportGrid* grid = nullptr;   ///< the file
  std::string heat_map;               ///< image file name
  const ReportCell* cell = nullptr;   ///< the cell of the stage bars
  std::string stage_bars;             ///< image file name
};

/// One time-against-error chart.
struct ParetoFigure {
  std::string family;      ///< "fracture" or "stress"
  std::string case_name;   ///< the case
  std::string image;       ///< image file name
};

/// What was drawn for one accuracy file.
struct AccuracyFigures {
  const ReportAccuracy* accuracy = nullptr;  ///< the file
  std::vector<ParetoFigure> charts;          ///< per family and case
};

/// The page: per grid file its heat map, the worst-frame table (rows pre-fracture, columns runtime,
/// over-budget cells bold with "!"), the stage bars and stage table of the chosen cell; per accuracy
/// file its charts and its tables; per stability file its verdicts and per table file its rows.
std::string report_page(const std::vector<GridFigures>& grids, const std::vector<AccuracyFigures>& accuracies,
                        const std::vector<ReportStability>& stabilities, const std::vector<ReportTable>& tables);

}  // namespace shatter
