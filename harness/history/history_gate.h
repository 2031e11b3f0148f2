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
///  - the newest commit's samples are tested against the baseline's with the two-sided Mann-Whitney U
///    test. The newest regresses when its median moved the wrong way by more than `threshold`
///    (relative) and by at least the unit's absolute floor, and p < `alpha`. A move the right way that
///    passes the same bar is an improvement, reported and never failed; anything less is "same", so
///    noise is never reported as an improvement either.
///  - A series whose every commit holds fewer samples than the test needs (one value per run, e.g. an
///    accuracy figure, which is deterministic) is judged by the thresholds alone.

#include "algorithms/core/result.h"
#include "harness/history/series_points.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shatter {

/// The gate's parameters, with their defaults (flags of `history gate`).
struct HistoryGateSettings {
  int recent = 5;                ///< a change point among this many newest commits keeps its step in view
  double threshold = 0.05;       ///< smallest relative change that regresses
  double alpha = 0.01;           ///< significance level of the U test
  double min_change_ms = 0.01;   ///< series in ms: smallest absolute change that regresses, ms
  double min_change_other = 1e-9;  ///< other series: smallest absolute change (error figures are ratios near 0)
  int baseline_commits = 30;     ///< most commits in the baseline
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
  double change = 0.0;             ///< new / base - 1 (0 when base is 0)
  double pvalue = -1.0;            ///< U test; < 0 when not tested (too few samples)
  std::size_t baseline_first = 0;  ///< index of the baseline's first commit in the points
  std::size_t baseline_size = 0;   ///< commits in the baseline
  std::string note;                ///< why, in words (e.g. "stepped at 1a2b3c4d5e6f, 2 commits ago")
};

/// Judges the last of `points` against the ones before it, from `first` (the acknowledged commit's
/// index, 0 when none). `unit` picks the absolute floor.
SeriesVerdict judge_newest(const std::vector<CommitPoint>& points, std::size_t first, Better better,
                           const std::string& unit, const HistoryGateSettings& settings);

}  // namespace shatter
