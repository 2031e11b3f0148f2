#pragma once
/// The two-sided Mann-Whitney U test (Wilcoxon rank-sum) on two independent samples, as Google
/// Benchmark's compare.py uses it on repetition samples.
///
/// U of the first sample = R1 - n1 (n1 + 1) / 2, with R1 its rank sum (tied values get the mean of the
/// ranks they span). The p-value is exact when there are no ties and n1 n2 <= 10,000 (the null
/// distribution of U counted by the recurrence f(n1, n2, u) = f(n1 - 1, n2, u - n2) + f(n1, n2 - 1, u)),
/// otherwise the normal approximation with the tie-corrected variance and a continuity correction.
/// Two-sided: p = min(1, 2 min(P(U <= u), P(U >= u))).

#include <span>

namespace shatter {

/// Result of one test.
struct MannWhitneyResult {
  double u = 0.0;          ///< U of the first sample
  double p_value = 1.0;    ///< two-sided
  bool exact = false;      ///< p from the exact distribution (else the normal approximation)
};

/// The test of `a` against `b` (finite values; either empty gives p = 1).
MannWhitneyResult mann_whitney_u(std::span<const double> a, std::span<const double> b);

/// The smallest two-sided p-value any pair of samples of sizes n1 and n2 can reach (no ties): below
/// the significance level, no difference can be shown (2 / C(n1 + n2, n1)).
double smallest_p_value(int n1, int n2);

}  // namespace shatter
