#include "harness/history/history_gate.h"

#include "harness/compare/mann_whitney.h"
#include "harness/results/sample_statistics.h"

#include <boost/math/distributions/students_t.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace shatter {

Status check_history_gate_settings(const HistoryGateSettings& s) {
  if (s.recent < 1) return Error{"--recent: at least 1"};
  if (!(s.threshold >= 0.0 && s.threshold < 1e6)) return Error{"--threshold: at least 0"};
  if (!(s.alpha > 0.0 && s.alpha < 1.0)) return Error{"--alpha: in (0, 1)"};
  if (!(s.min_change_ms >= 0.0)) return Error{"--min-change-ms: at least 0"};
  if (s.baseline_commits < 1) return Error{"--baseline-commits: at least 1"};
  if (s.test != "medians" && s.test != "robust" && s.test != "samples")
    return Error{"--test: medians, robust or samples, got \"" + s.test + "\""};
  if (s.change_points.window < 2) return Error{"--window: at least 2"};
  if (!(s.change_points.max_pvalue > 0.0 && s.change_points.max_pvalue <= 1.0)) return Error{"--max-pvalue: in (0, 1]"};
  return {};
}

const char* gate_verdict_name(GateVerdict v) {
  switch (v) {
    case GateVerdict::same: return "same";
    case GateVerdict::improved: return "improved";
    case GateVerdict::regressed: return "regressed";
    case GateVerdict::no_baseline: return "new";
  }
  return "same";
}

double prediction_pvalue(double value, std::span<const double> baseline) {
  const std::size_t n = baseline.size();
  if (n < 2) return 1.0;
  double mean = 0.0;
  for (double b : baseline) mean += b;
  mean /= static_cast<double>(n);
  double ss = 0.0;
  for (double b : baseline) ss += (b - mean) * (b - mean);
  const double sd = std::sqrt(ss / static_cast<double>(n - 1));
  if (!(sd > 0.0)) return value == mean ? 1.0 : 0.0;
  const double t = (value - mean) / (sd * std::sqrt(1.0 + 1.0 / static_cast<double>(n)));
  if (!std::isfinite(t)) return 1.0;  // beyond what the statistics can hold: no evidence
  const boost::math::students_t student(static_cast<double>(n - 1));
  return std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(student, std::abs(t))));
}

double robust_prediction_pvalue(double value, std::span<const double> baseline) {
  const std::size_t n = baseline.size();
  if (n < 2) return 1.0;
  const double center = median_of(baseline);
  std::vector<double> deviations;
  for (double b : baseline) deviations.push_back(std::abs(b - center));
  const double scale = 1.4826 * median_of(deviations);
  if (!(scale > 0.0)) return value == center ? 1.0 : 0.0;
  const double t = (value - center) / (scale * std::sqrt(1.0 + 1.0 / static_cast<double>(n)));
  if (!std::isfinite(t)) return 1.0;
  const boost::math::students_t student(static_cast<double>(n - 1));
  return std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(student, std::abs(t))));
}

SeriesVerdict judge_newest(const std::vector<CommitPoint>& points, std::size_t first, Better better,
                           const std::string& unit, const HistoryGateSettings& settings) {
  SeriesVerdict v;
  if (points.empty()) return v;
  const std::size_t n = points.size();
  const CommitPoint& newest = points.back();
  v.new_median = newest.median;
  if (first >= n - 1) {
    v.verdict = GateVerdict::no_baseline;
    v.note = first == 0 ? "first commit of the series" : "acknowledged at this commit";
    return v;
  }
  const std::vector<CommitPoint> judged(points.begin() + static_cast<std::ptrdiff_t>(first), points.end());
  const std::vector<SeriesChange> changes = series_changes(judged, better, settings.change_points);
  // Segment boundaries within `judged`; the newest commit is index judged.size() - 1.
  const std::size_t last = judged.size() - 1;
  const std::size_t recent_from = last + 1 > static_cast<std::size_t>(settings.recent) ? last + 1 - settings.recent : 0;
  std::size_t begin = 0, end = last;  // baseline [begin, end)
  const SeriesChange* recent_step = nullptr;
  for (const SeriesChange& c : changes)
    if (c.index >= recent_from && c.index <= last && recent_step == nullptr) recent_step = &c;
  if (recent_step != nullptr) {
    end = recent_step->index;
    for (const SeriesChange& c : changes)
      if (c.index < end) begin = c.index;
    v.note = fmt::format("stepped at {} ({} commit{} ago)", recent_step->commit.substr(0, 12), last - recent_step->index,
                         last - recent_step->index == 1 ? "" : "s");
  } else {
    for (const SeriesChange& c : changes)
      if (c.index < last) begin = c.index;
  }
  if (end <= begin) {  // a step at the first commit of the history: nothing before it to compare with
    v.verdict = GateVerdict::no_baseline;
    v.note = "no stable segment before the newest commit";
    return v;
  }
  if (end - begin > static_cast<std::size_t>(settings.baseline_commits)) begin = end - settings.baseline_commits;
  v.baseline_first = first + begin;
  v.baseline_size = end - begin;

  std::vector<double> base_medians, base_samples;
  std::size_t most_samples = newest.samples.size();
  for (std::size_t i = begin; i < end; ++i) {
    base_medians.push_back(judged[i].median);
    base_samples.insert(base_samples.end(), judged[i].samples.begin(), judged[i].samples.end());
    most_samples = std::max(most_samples, judged[i].samples.size());
  }
  v.base_median = median_of(base_medians);
  v.change = v.base_median != 0.0 ? (v.new_median - v.base_median) / std::abs(v.base_median) : 0.0;
  const double absolute = std::abs(v.new_median - v.base_median);
  const double floor = unit == "ms" ? settings.min_change_ms : settings.min_change_other;
  bool significant = true;
  if (settings.test != "samples" && base_medians.size() >= 3 && most_samples >= 2) {
    // The run as the unit that varies: the newest commit's median against the spread of the
    // baseline's commit medians.
    v.pvalue = settings.test == "robust" ? robust_prediction_pvalue(v.new_median, base_medians)
                                         : prediction_pvalue(v.new_median, base_medians);
    significant = v.pvalue < settings.alpha;
  } else if (newest.samples.size() >= 2 && smallest_p_value(static_cast<int>(newest.samples.size()),
                                                     static_cast<int>(std::min<std::size_t>(base_samples.size(), 1000))) < settings.alpha) {
    v.pvalue = mann_whitney_u(newest.samples, base_samples).p_value;
    significant = v.pvalue < settings.alpha;
  } else if (most_samples >= 2) {
    significant = false;  // a timing with too few samples at the newest commit cannot show a change
    v.note = v.note.empty() ? "too few samples at the newest commit for the U test" : v.note;
  }
  const bool large = std::abs(v.change) > settings.threshold && absolute >= floor;
  const ChangeKind kind = classify_change(v.base_median == 0.0 ? (v.new_median - v.base_median) : v.change, better);
  if (large && significant && kind == ChangeKind::regression) v.verdict = GateVerdict::regressed;
  else if (large && significant && kind == ChangeKind::improvement) v.verdict = GateVerdict::improved;
  if (v.base_median == 0.0 && absolute >= floor && kind != ChangeKind::neutral && significant)
    v.verdict = kind == ChangeKind::regression ? GateVerdict::regressed : GateVerdict::improved;
  return v;
}

}  // namespace shatter
