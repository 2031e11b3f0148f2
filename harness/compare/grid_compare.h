#pragma once
/// `compare`: a new grid result against a baseline, per cell and per stage (docs/compare.md).
///
/// Design note: a timing regresses only when two conditions hold, as in asv and Blast: the median
/// got slower by more than `max_slowdown` (relative, the effect is large enough to matter) AND the
/// two-sided Mann-Whitney U test on the per-repetition samples gives p < `alpha` (the effect is not
/// noise). Either alone cries wolf: a threshold alone fails on a noisy runner, a test alone fails on
/// a 0.5 % change with many samples. Instruction counts are deterministic up to a measured variation
/// far below any threshold, so in instruction mode the relative threshold alone decides. Accuracy
/// figures never go through statistics: they regress against fixed tolerances. Improvements are
/// reported, never failed.

#include "algorithms/core/result.h"
#include "harness/results/grid_reader.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shatter {

/// Settings of a comparison.
struct CompareOptions {
  double max_slowdown = 0.05;      ///< relative slowdown of a median that can regress, > 0
  double alpha = 0.01;             ///< significance level of the U test, in (0, 1)
  std::string metric = "time";     ///< "time" (ms, statistical) or "instructions" (counts, threshold)
  /// Time mode: a change smaller than this (ms, absolute, of the median) never regresses: stages of a
  /// few microseconds (the bond update, the falling-cluster search) move by more than 5 % with timer
  /// noise alone. >= 0.
  double min_change_ms = 0.01;
  /// Time mode: "cpu" (the thread's CPU time per stage and of the frame with the most of it; the
  /// default, steadier on a shared runner: time spent descheduled does not count) or "wall".
  std::string clock = "cpu";
  /// CPU clock: divide each repetition's times by its calibration time (harness/grid/calibration.h)
  /// and scale by the baseline's median calibration, so that a busier machine does not read as a
  /// regression. Used when every sample on both sides carries a calibration time.
  bool normalize = true;
};

/// Tolerances of the accuracy figures (absolute increases that fail).
struct AccuracyTolerances {
  double volume_error = 1e-9;      ///< relative volume error may grow by this much
  double partition_error = 2e-3;   ///< share of sampled points (256 samples: about half a point)
};

/// What one row of the comparison says.
enum class Verdict { same, improved, regressed, failed };

/// One row: a cell's worst frame, one of its stages, or its accuracy.
struct ComparisonRow {
  std::string cell;                ///< "100 x 25"
  std::string what;                ///< "worst frame", "stage stress", "accuracy"
  double base_median = 0.0;        ///< per-repetition medians (ms or instructions)
  double new_median = 0.0;
  double change = 0.0;             ///< new / base - 1; 0 when not change_defined
  /// False when the base median is 0 (or so small that new / base is not finite): the relative change
  /// is then undefined and the row is judged by the absolute change (printed instead of a percentage).
  bool change_defined = true;
  double base_p99 = 0.0;           ///< 0.99-quantile (type 7): of every frame for "worst frame", else of the repetitions
  double new_p99 = 0.0;
  double p_value = -1.0;           ///< two-sided U test; < 0 when not tested (instructions, accuracy)
  Verdict verdict = Verdict::same;
  std::string note;                ///< why, for regressions, failures and skipped tests
};

/// The whole comparison.
struct CompareReport {
  std::vector<ComparisonRow> rows;
  std::vector<std::string> mismatches;  ///< reasons the results cannot be compared (each fails)
  std::vector<std::string> warnings;    ///< e.g. too few repetitions for the test to ever fire
  std::string metric;                   ///< as compared
  double base_calibration_ms = 0.0;     ///< median calibration time of the baseline (0: none)
  double new_calibration_ms = 0.0;      ///< and of the new results
  bool normalized = false;              ///< times were divided by the calibration

  /// True when a row regressed or failed, or the results could not be compared.
  [[nodiscard]] bool failed() const;
};

/// Checks `options` (error names the flag).
Status check_compare_options(const CompareOptions& options);

/// Compares `next` against `base`. Mismatches (fingerprint, case, a missing cell, instruction counts
/// missing in instruction mode) are reported in the report, not as errors.
CompareReport compare_grids(const StoredGrid& base, const StoredGrid& next, const CompareOptions& options,
                            const AccuracyTolerances& tolerances = {});

/// The report as Markdown (compare's standard output): the verdict line, mismatches, warnings, and a
/// table of every row (regressions and failures first, then improvements, then the rest).
std::string compare_markdown(const CompareReport& report, const CompareOptions& options);

/// GitHub's limit on a comment's body is 65,536 characters; this leaves room for a header of the CI's.
inline constexpr std::size_t kCommentChars = 65000;

/// The report as a pull-request comment (`compare --markdown FILE`): the verdict line, mismatches and
/// warnings, the regressions and failures in a table of their own, then every row in a table folded
/// in `<details>`; at most `max_chars` characters (rows that do not fit are counted, not shown).
std::string compare_comment_markdown(const CompareReport& report, const CompareOptions& options,
                                     std::size_t max_chars = kCommentChars);

}  // namespace shatter
