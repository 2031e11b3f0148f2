#include "algorithms/stress/rigid_body_spring/analysis_pool.h"

#include <algorithm>
#include <utility>

namespace shatter {
namespace {

/// FNV-1a over the 32-bit words of `values`, continuing from `h`.
std::uint64_t mix(std::uint64_t h, const std::vector<int>& values) {
  for (const int v : values) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
  return (h ^ values.size()) * 1099511628211ull;
}

}  // namespace

FactorPattern::FactorPattern(const Eigen::SparseMatrix<double>& lower, std::span<const int> node_groups)
    : outer(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.outerSize() + 1),
      inner(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros()),
      groups(node_groups.begin(), node_groups.end()) {
  hash = mix(mix(mix(14695981039346656037ull, outer), inner), groups);
}

std::optional<SparseCholesky> AnalysisPool::take(const FactorPattern& pattern, const Eigen::SparseMatrix<double>& lower) {
  BoundedStore<Entry>& p = store_;
  if (std::optional<Entry> found =
          p.take([&](const Entry& e) { return e.pattern.hash == pattern.hash && e.pattern == pattern; })) {
    ++p.reuses;
    return std::move(found->factor);
  }
  SparseCholesky factor;
  if (!factor.analyze(lower, pattern.groups)) return std::nullopt;
  return factor;
}

void AnalysisPool::keep(FactorPattern pattern, SparseCholesky factor) {
  const std::size_t bytes = factor.factor_bytes() + sizeof(int) * (pattern.outer.size() + pattern.inner.size() + pattern.groups.size());
  store_.keep(Entry{std::move(pattern), std::move(factor), bytes}, [](Entry&) {});
}

}  // namespace shatter
