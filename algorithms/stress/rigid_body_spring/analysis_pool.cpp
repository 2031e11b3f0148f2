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

struct Entry {
  FactorPattern pattern;
  SupernodalCholesky factor;
  std::size_t bytes;
};

struct Pool {
  std::vector<Entry> entries;  // oldest first
  std::size_t bytes = 0;
  std::size_t reuses = 0;
};

Pool& pool() {
  thread_local Pool p;
  return p;
}

}  // namespace

FactorPattern::FactorPattern(const Eigen::SparseMatrix<double>& lower, std::span<const int> node_groups)
    : outer(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.outerSize() + 1),
      inner(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros()),
      groups(node_groups.begin(), node_groups.end()) {
  hash = mix(mix(mix(14695981039346656037ull, outer), inner), groups);
}

std::optional<SupernodalCholesky> take_analysed(const FactorPattern& pattern, const Eigen::SparseMatrix<double>& lower) {
  Pool& p = pool();
  const auto found = std::find_if(p.entries.begin(), p.entries.end(),
                                  [&](const Entry& e) { return e.pattern.hash == pattern.hash && e.pattern == pattern; });
  if (found != p.entries.end()) {
    SupernodalCholesky factor = std::move(found->factor);
    p.bytes -= found->bytes;
    p.entries.erase(found);
    ++p.reuses;
    return factor;
  }
  SupernodalCholesky factor;
  if (!factor.analyze(lower, pattern.groups)) return std::nullopt;
  return factor;
}

void keep_analysed(FactorPattern pattern, SupernodalCholesky factor) {
  Pool& p = pool();
  const std::size_t bytes = factor.factor_bytes() + sizeof(int) * (pattern.outer.size() + pattern.inner.size() + pattern.groups.size());
  if (bytes > kMaxPooledBytes) return;
  while (!p.entries.empty() && (p.entries.size() >= kMaxPooledFactors || p.bytes + bytes > kMaxPooledBytes)) {
    p.bytes -= p.entries.front().bytes;
    p.entries.erase(p.entries.begin());
  }
  p.bytes += bytes;
  p.entries.push_back(Entry{std::move(pattern), std::move(factor), bytes});
}

void forget_analysed() {
  Pool& p = pool();
  p.entries.clear();
  p.bytes = 0;
}

std::size_t analysed_reuses() { return pool().reuses; }

}  // namespace shatter
