#pragma once
/// The gate on the history (docs/history.md, "The gate"): is the newest commit of a series a
/// regression against the series' last stable segment?
///
/// Per series, over the commits from its latest acknowledgement (or its first) to the gated one:
///  - the change points of the commit medians are found (series_changes);
///  - the baseline is the last stable segment: the commits since the last change point, or, when a
///    change point lies among the last `recent` commits, the segment before that change point (a step
///    that landed a few commits ago stays a regression until it is acknowledged); at most
///    `baseline_commits` commits;
///  - the newest commit's samples are tested against the baseline's (`test`): by default with the
///    two-sided Mann-Whitney U test over every sample; or the newest commit's median against the
///    spread of the baseline's commit medians (Student's t prediction test, plain or robust). The
///    newest regresses when its median moved the wrong way by more than `threshold` (relative) and by
///    at least the unit's absolute floor, and p < `alpha`. A move the right way that
///    passes the same bar is an improvement, reported and never failed; anything less is "same", so
///    noise is never reported as an improvement either.
///  - A series whose every commit holds fewer samples than the test needs (one value per run, e.g. an
///    accuracy figure, which is deterministic) is judged by the thresholds alone.

#include "algorithms/core/result.h"
#include "harness/history/series_points.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace shatter {

/// The gate's parameters, with their defaults (flags of `history gate`).
struct HistoryGateSettings {
  int recent = 5;                ///< a change point among this many newest commits keeps its step in view
  double threshold = 0.05;       ///< smallest relative change that regresses
  double alpha = 0.01;           ///< significance level of the U test
  /// Series in ms: smallest absolute change that regresses, ms (1/600 of a 30 fps frame: the stages of
  /// a few tenths of a millisecond move by that much between runs of one build, docs/history.md).
  double min_change_ms = 0.05;
  double min_change_other = 1e-9;  ///< other series: smallest absolute change (error figures are ratios near 0)
  int baseline_commits = 30;     ///< most commits in the baseline
  /// How the newest commit is tested against the baseline: "medians" (the prediction test on the
  /// commit medians), "robust" (the same with the median and 1.4826 x the median absolute deviation,
  /// which a few outlying runs in the baseline do not widen) or "samples" (the U test on every sample).
  std::string test = "samples";
  ChangePointSettings change_points;  ///< for the segments
};

/// Error when a setting is out of range (names the flag).
Status check_history_gate_settings(const HistoryGateSettings& s);

/// What the gate says of one series.
enum class GateVerdict { same, improved, regressed, no_baseline };

/// "same", "improved", "regressed", "new".
const char* gate_verdict_name(GateVerdict v);

/// The verdict of one series and what it rests on.
struct SeriesVerdict {
  GateVerdict verdict = GateVerdict::same;
  double base_median = 0.0;        ///< median of the baseline's commit medians
  double new_median = 0.0;         ///< median of the newest commit's samples
  double change = 0.0;             ///< (new - base) / |base| (0 when base is 0)
  double pvalue = -1.0;            ///< the test's; < 0 when not tested (too few samples)
  std::size_t baseline_first = 0;  ///< index of the baseline's first commit in the points
  std::size_t baseline_size = 0;   ///< commits in the baseline
  std::string note;                ///< why, in words (e.g. "stepped at 1a2b3c4d5e6f, 2 commits ago")
};

/// Two-sided p-value of `value` as one more draw from the distribution of `baseline` (at least 2
/// values): t = (value - mean) / (s sqrt(1 + 1/n)), Student's t with n - 1 degrees of freedom. A
/// baseline without spread gives 1 for its own value and 0 for any other.
double prediction_pvalue(double value, std::span<const double> baseline);

/// The same with the baseline's median for its mean and 1.4826 x its median absolute deviation for
/// its standard deviation (both equal to them for normal data).
double robust_prediction_pvalue(double value, std::span<const double> baseline);

/// Judges the last of `points` against the ones before it, from `first` (the acknowledged commit's
/// index, 0 when none). `unit` picks the absolute floor.
SeriesVerdict judge_newest(const std::vector<CommitPoint>& points, std::size_t first, Better better,
                           const std::string& unit, const HistoryGateSettings& settings);

}  // namespace shatter
