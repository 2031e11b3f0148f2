#pragma once
/// What the history dashboard (`history report`, dashboard.html) draws, as one JSON value: every
/// series of a filter with its commits' medians and spread, its change points, and the gate's verdict
/// of its newest commit, series with an open regression first. The page downsamples what it draws;
/// this keeps every commit, so that a hover always shows the data.

#include "algorithms/core/result.h"
#include "harness/history/history_gate.h"
#include "harness/history/store/history_store.h"

#include <nlohmann/json.hpp>

namespace shatter {

/// The dashboard's data from `store`:
///   {"store", "commits": [{"sha", "time", "branch"}, ...] (in commit order),
///    "series": [{"kind", "case", "subject", "what", "metric", "unit", "better", "fingerprint",
///                "points": [[commit index, median, smallest, largest, samples], ...],
///                "changes": [{"index" (into points), "commit", "before", "after", "change", "pvalue", "kind"}],
///                "newest": {"verdict", "change", "pvalue", "note"}}, ...]}
/// Series whose newest commit regressed come first, then the others in the store's order.
Result<nlohmann::json> dashboard_data(HistoryStore& store, const SeriesFilter& filter, const HistoryGateSettings& gate);

}  // namespace shatter
