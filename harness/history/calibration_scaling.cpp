#include "harness/history/calibration_scaling.h"

#include "harness/results/sample_statistics.h"

#include <cmath>

namespace shatter {

bool normalize_by_calibration(std::vector<SeriesRun>& runs, const RunCalibrations& calibration) {
  std::vector<double> all;
  for (const SeriesRun& run : runs) {
    const auto it = calibration.find(run.run_id);
    if (it == calibration.end() || it->second.size() != run.samples.size()) return false;
    for (double c : it->second) {
      if (!(c > 0.0)) return false;
      all.push_back(c);
    }
  }
  if (all.empty()) return false;
  const double reference = median_of(all);
  // A calibration so small that the scale overflows (compare refuses it the same way).
  for (double c : all)
    if (!std::isfinite(reference / c)) return false;
  for (SeriesRun& run : runs) {
    const std::vector<double>& c = calibration.at(run.run_id);
    for (std::size_t k = 0; k < run.samples.size(); ++k) run.samples[k] *= reference / c[k];
  }
  return true;
}

}  // namespace shatter
