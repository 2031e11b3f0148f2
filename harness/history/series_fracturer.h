#pragma once
/// Which algorithm a stored series measured, read from its subject, for the dashboard's filter.

#include "harness/history/store/history_model.h"

#include <string>

namespace shatter {

/// The algorithm of `key`: a grid cell's runtime fracturer (the middle name of the subject's
/// "P x R prefracturer/fracturer/stress"), an accuracy point's algorithm (the first word of
/// "ALGORITHM KNOB": a fracturer, or a stress model in the stress family), a table row's fracturer
/// (the first word of "FRACTURER N fragments"); "" when the subject has no such part.
std::string series_fracturer(const SeriesKey& key);

}  // namespace shatter
