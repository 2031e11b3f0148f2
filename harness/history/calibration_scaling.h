#pragma once
/// CPU times of a grid made comparable across a busier and a quieter machine, as `compare` makes them
/// (harness/grid/calibration.h): every repetition of a grid run also times a fixed reference workload
/// (its `calibration` series); a CPU time divided by its own repetition's calibration time and scaled
/// by the median calibration of the runs judged together no longer moves with the machine's speed.

#include "harness/history/store/history_model.h"

#include <map>
#include <string>
#include <vector>

namespace shatter {

/// A run's calibration samples (one per repetition), by run id.
using RunCalibrations = std::map<std::string, std::vector<double>>;

/// Divides every sample of `runs` by its repetition's calibration time and multiplies it by the median
/// of every calibration sample of these runs. When a run has no calibration, or not one per sample,
/// or one that is not positive, nothing is changed and the answer is false.
bool normalize_by_calibration(std::vector<SeriesRun>& runs, const RunCalibrations& calibration);

}  // namespace shatter
