#include "algorithms/stress/rigid_body_spring/solved_systems.h"

#include "algorithms/stress/rigid_body_spring/linear_solve.h"

#include <algorithm>
#include <utility>

namespace shatter {
namespace {

/// Hands a block's factor to the analysis pool (its analysis stays useful for the same pattern).
void pool_factor(SolvedBlock& block, AnalysisPool& pool) {
  if (block.factor) pool.keep(std::move(*block.pattern), std::move(*block.factor));
  block.factor.reset();
}

}  // namespace

std::optional<std::vector<SolvedBlock>> SolvedSystems::take(const Eigen::SparseMatrix<double>& k,
                                                             const SpringSolverSettings& settings, AnalysisPool& pool) {
  std::optional<System> found = store_.take([&](const System& e) {
    const Eigen::SparseMatrix<double>& kept = *e.k;
    return kept.cols() == k.cols() && kept.nonZeros() == k.nonZeros() &&
           e.decoupling_tolerance == settings.decoupling_tolerance && e.direct_max_flops == settings.direct_max_flops &&
           std::equal(kept.outerIndexPtr(), kept.outerIndexPtr() + kept.cols() + 1, k.outerIndexPtr()) &&
           std::equal(kept.innerIndexPtr(), kept.innerIndexPtr() + kept.nonZeros(), k.innerIndexPtr());
  });
  if (!found) return std::nullopt;
  if (std::equal(found->k->valuePtr(), found->k->valuePtr() + found->k->nonZeros(), k.valuePtr())) {
    ++store_.reuses;
    return std::move(found->blocks);
  }
  for (SolvedBlock& block : found->blocks) pool_factor(block, pool);
  return std::nullopt;
}

void SolvedSystems::keep(Eigen::SparseMatrix<double>& k, const SpringSolverSettings& settings,
                         std::vector<SolvedBlock> blocks, AnalysisPool& pool) {
  std::size_t bytes = static_cast<std::size_t>(k.nonZeros()) * (sizeof(double) + sizeof(int));
  for (const SolvedBlock& block : blocks) bytes += block.factor ? block.factor->factor_bytes() : 0;
  if (bytes > kMaxPooledBytes) {
    for (SolvedBlock& block : blocks) pool_factor(block, pool);
    return;
  }
  System e;
  e.k = std::make_unique<Eigen::SparseMatrix<double>>();
  e.k->swap(k);
  e.decoupling_tolerance = settings.decoupling_tolerance;
  e.direct_max_flops = settings.direct_max_flops;
  e.blocks = std::move(blocks);
  e.bytes = bytes;
  store_.keep(std::move(e), [&](System& dropped) {
    for (SolvedBlock& block : dropped.blocks) pool_factor(block, pool);
  });
}

}  // namespace shatter
