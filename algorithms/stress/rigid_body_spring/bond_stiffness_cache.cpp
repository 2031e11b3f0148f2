#include "algorithms/stress/rigid_body_spring/bond_stiffness_cache.h"

#include "algorithms/stress/rigid_body_spring/stiffness_pattern.h"

namespace shatter {

void compute_bond_stiffness(const SupportGraph& graph, int bond, const Material& material, BondStiffness& out) {
  out.spring = bond_spring(graph, bond, material);
  bond_blocks(out.spring, out.blocks);
  for (std::size_t q = 0; q < 4; ++q) out.masks[q] = nonzero_mask(out.blocks[q]);
}

BondStiffnessCache::BondStiffnessCache(const SupportGraph& graph, const Material& material)
    : graph_(&graph), material_(material), slot_(graph.bonds.size(), -1) {
  // Room for every bond at once: entries never move (references stay valid), and the pages of bonds no
  // window reaches are never touched.
  entries_.reserve(graph.bonds.size());
}

void BondStiffnessCache::prepare(std::span<const int> bonds) {
  for (const int b : bonds) {
    int& slot = slot_[static_cast<std::size_t>(b)];
    if (slot >= 0) continue;
    slot = static_cast<int>(entries_.size());
    compute_bond_stiffness(*graph_, b, material_, entries_.emplace_back());
  }
}

}  // namespace shatter
