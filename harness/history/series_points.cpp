#include "harness/history/series_points.h"

#include "harness/results/sample_statistics.h"

#include <algorithm>
#include <cmath>

namespace shatter {

std::vector<CommitPoint> commit_points(const std::vector<SeriesRun>& runs) {
  std::vector<CommitPoint> points;
  for (const SeriesRun& run : runs) {
    if (points.empty() || points.back().commit != run.commit) points.push_back(CommitPoint{run.commit, run.commit_time, run.branch, {}, 0.0, true, run.generation});
    CommitPoint& p = points.back();
    p.samples.insert(p.samples.end(), run.samples.begin(), run.samples.end());
    p.passed = p.passed && run.passed;
  }
  for (CommitPoint& p : points) p.median = median_of(p.samples);
  return points;
}

const char* change_kind_name(ChangeKind k) {
  switch (k) {
    case ChangeKind::regression: return "regression";
    case ChangeKind::improvement: return "improvement";
    case ChangeKind::neutral: return "change";
  }
  return "change";
}

ChangeKind classify_change(double change, Better better) {
  if (better == Better::none || change == 0.0) return ChangeKind::neutral;
  const bool worse = better == Better::lower ? change > 0.0 : change < 0.0;
  return worse ? ChangeKind::regression : ChangeKind::improvement;
}

std::vector<SeriesChange> series_changes(const std::vector<CommitPoint>& points, Better better,
                                         const ChangePointSettings& settings) {
  std::vector<double> medians;
  medians.reserve(points.size());
  for (const CommitPoint& p : points) medians.push_back(p.median);
  const std::vector<SeriesChangePoint> found = find_change_points(medians, settings);
  std::vector<SeriesChange> out;
  for (std::size_t i = 0; i < found.size(); ++i) {
    const std::size_t begin = i == 0 ? 0 : found[i - 1].index;
    const std::size_t at = found[i].index;
    const std::size_t end = i + 1 < found.size() ? found[i + 1].index : medians.size();
    SeriesChange c;
    c.index = at;
    c.commit = points[at].commit;
    c.median_before = median_of(std::span<const double>(medians).subspan(begin, at - begin));
    c.median_after = median_of(std::span<const double>(medians).subspan(at, end - at));
    c.change = c.median_before != 0.0 ? (c.median_after - c.median_before) / std::abs(c.median_before) : 0.0;
    c.pvalue = found[i].pvalue;
    c.kind = classify_change(c.change, better);
    out.push_back(c);
  }
  return out;
}

}  // namespace shatter
