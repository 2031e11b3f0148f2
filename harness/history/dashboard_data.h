#pragma once
/// What the history dashboard (`history report`, dashboard.html; docs/dashboard.md) draws, as one JSON
/// value: every series of a filter with its commits' medians and spread, its change points, and the
/// gate's verdict of its newest commit, series with an open regression first. The page downsamples what
/// it draws; this keeps every commit, so that a hover always shows the data.

#include "algorithms/core/result.h"
#include "harness/history/history_gate.h"
#include "harness/history/store/history_store.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>

namespace shatter {

/// The version of the dashboard data's layout (its `format`).
inline constexpr int kDashboardDataFormat = 1;

/// The dashboard's data from `store`, over commits at or after `since_time` (committer time, s):
///   {"format", "store", "settings": {"window", "max_pvalue", "min_magnitude"},
///    "commits": [{"sha", "time", "branch"}, ...] (in commit order: committer time, generation, sha),
///    "series": [{"id" (the series id as 16 hex digits), "kind", "case", "subject", "what", "metric",
///                "unit", "better", "fingerprint", "fracturer" (series_fracturer),
///                "points": [[commit index, median, smallest, largest, samples], ...] (commit order),
///                "changes": [{"index" (into points), "commit", "before", "after", "change", "pvalue", "kind"}],
///                "newest": {"verdict", "change", "pvalue", "note", "acknowledged": {"commit", "note"} (when one
///                           applies)} (series with a direction only)}, ...]}
/// The newest commit is judged as `history gate` judges it (judge_newest), from the series' latest
/// acknowledgement on, on the raw samples (no calibration). Series whose newest commit regressed come first, then the others in the store's order. Only series
/// with a point in the window are listed.
Result<nlohmann::json> dashboard_data(HistoryStore& store, const SeriesFilter& filter, const HistoryGateSettings& gate,
                                      std::int64_t since_time = std::numeric_limits<std::int64_t>::min());

}  // namespace shatter
