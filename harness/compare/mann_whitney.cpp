#include "harness/compare/mann_whitney.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace shatter {
namespace {

/// Number of arrangements of n1 x's and n2 y's with U = u, for every u in [0, n1 n2], divided by
/// C(n1 + n2, n1): the exact null distribution of U.
std::vector<double> u_distribution(int n1, int n2) {
  // count[i][j][u] computed row by row over i with a rolling table over j.
  const int max_u = n1 * n2;
  // f[j][u] for the current i.
  std::vector<std::vector<double>> f(static_cast<std::size_t>(n2) + 1,
                                     std::vector<double>(static_cast<std::size_t>(max_u) + 1, 0.0));
  for (int j = 0; j <= n2; ++j) f[static_cast<std::size_t>(j)][0] = 1.0;  // i = 0: one arrangement, U = 0
  for (int i = 1; i <= n1; ++i) {
    std::vector<std::vector<double>> g(static_cast<std::size_t>(n2) + 1,
                                       std::vector<double>(static_cast<std::size_t>(max_u) + 1, 0.0));
    g[0][0] = 1.0;  // j = 0: U = 0
    for (int j = 1; j <= n2; ++j) {
      for (int u = 0; u <= i * j; ++u) {
        // The largest value is an x (it beats all j y's: u - j from the rest) or a y.
        double c = g[static_cast<std::size_t>(j - 1)][static_cast<std::size_t>(u)];
        if (u >= j) c += f[static_cast<std::size_t>(j)][static_cast<std::size_t>(u - j)];
        g[static_cast<std::size_t>(j)][static_cast<std::size_t>(u)] = c;
      }
    }
    f = std::move(g);
  }
  std::vector<double> p = f[static_cast<std::size_t>(n2)];
  const double total = std::accumulate(p.begin(), p.end(), 0.0);
  for (double& v : p) v /= total;
  return p;
}

}  // namespace

double smallest_p_value(int n1, int n2) {
  if (n1 <= 0 || n2 <= 0) return 1.0;
  // 2 / C(n1 + n2, n1)
  double c = 1.0;
  for (int k = 1; k <= n1; ++k) c = c * (n2 + k) / k;
  return std::min(1.0, 2.0 / c);
}

MannWhitneyResult mann_whitney_u(std::span<const double> a, std::span<const double> b) {
  MannWhitneyResult out;
  const int n1 = static_cast<int>(a.size()), n2 = static_cast<int>(b.size());
  if (n1 == 0 || n2 == 0) return out;
  // Pool, sort, mid-ranks.
  std::vector<std::pair<double, int>> pooled;
  for (const double v : a) pooled.emplace_back(v, 0);
  for (const double v : b) pooled.emplace_back(v, 1);
  std::sort(pooled.begin(), pooled.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const int n = n1 + n2;
  double rank_sum_a = 0.0, tie_term = 0.0;
  bool ties = false;
  for (int i = 0; i < n;) {
    int j = i;
    while (j + 1 < n && pooled[static_cast<std::size_t>(j + 1)].first == pooled[static_cast<std::size_t>(i)].first) ++j;
    const double rank = 0.5 * (i + j) + 1.0;  // mean of ranks i+1 .. j+1
    const double t = j - i + 1;
    if (t > 1) {
      ties = true;
      tie_term += t * t * t - t;
    }
    for (int k = i; k <= j; ++k)
      if (pooled[static_cast<std::size_t>(k)].second == 0) rank_sum_a += rank;
    i = j + 1;
  }
  out.u = rank_sum_a - 0.5 * n1 * (n1 + 1.0);

  if (!ties && static_cast<long long>(n1) * n2 <= 10000) {
    const std::vector<double> p = u_distribution(n1, n2);
    const int u = static_cast<int>(std::lround(out.u));
    double below = 0.0, above = 0.0;
    for (int k = 0; k <= u; ++k) below += p[static_cast<std::size_t>(k)];
    for (int k = u; k <= n1 * n2; ++k) above += p[static_cast<std::size_t>(k)];
    out.p_value = std::min(1.0, 2.0 * std::min(below, above));
    out.exact = true;
    return out;
  }
  const double mean = 0.5 * n1 * n2;
  const double variance = n1 * n2 / 12.0 * ((n + 1.0) - tie_term / (static_cast<double>(n) * (n - 1.0)));
  if (!(variance > 0.0)) return out;  // every value equal: no evidence of a difference
  const double z = (std::abs(out.u - mean) - 0.5) / std::sqrt(variance);
  out.p_value = std::min(1.0, std::erfc(std::max(z, 0.0) / std::sqrt(2.0)));
  return out;
}

}  // namespace shatter
