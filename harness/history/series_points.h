#pragma once
/// A stored series as the analysis sees it: one point per commit, in commit order, with every sample
/// of every run at that commit pooled (two runs of one commit, e.g. a re-run, are more samples of it),
/// and the change points of that series in the terms the user reads: commit, median before and after,
/// relative change, p-value, and whether it is a regression by the metric's direction.

#include "harness/history/change_points.h"
#include "harness/history/store/history_model.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shatter {

/// One commit of a series.
struct CommitPoint {
  std::string commit;            ///< sha
  std::int64_t time = 0;         ///< committer time
  std::string branch;            ///< the commit's branch
  std::vector<double> samples;   ///< every sample of every run at the commit
  double median = 0.0;           ///< of the samples
  bool passed = true;            ///< every run at the commit passed its own checks
  std::int64_t generation = 0;   ///< of the commit (orders commits of one second)
};

/// `runs` (in commit order, as HistoryStore::series_runs returns them) pooled per commit.
std::vector<CommitPoint> commit_points(const std::vector<SeriesRun>& runs);

/// How a change reads by the metric's direction.
enum class ChangeKind { regression, improvement, neutral };

/// "regression", "improvement" or "change".
const char* change_kind_name(ChangeKind k);

/// The kind of a relative change `change` (new / old - 1) of a metric that is `better` when lower or
/// higher; a metric without a direction is neutral.
ChangeKind classify_change(double change, Better better);

/// One change point of a stored series.
struct SeriesChange {
  std::size_t index = 0;        ///< of the first commit of the new level
  std::string commit;           ///< its sha
  double median_before = 0.0;   ///< median of the commit medians of the segment before (back to the previous change point)
  double median_after = 0.0;    ///< and of the segment from it (to the next)
  double change = 0.0;          ///< (median_after - median_before) / |median_before| (0 when median_before is 0)
  double pvalue = 1.0;          ///< of the t-test (find_change_points)
  ChangeKind kind = ChangeKind::neutral;
};

/// The change points of the commit medians of `points`, at `settings`.
std::vector<SeriesChange> series_changes(const std::vector<CommitPoint>& points, Better better,
                                         const ChangePointSettings& settings);

}  // namespace shatter
