#pragma once
/// Each bond's spring, four stiffness blocks and their nonzero masks, computed at a bond's first use and
/// kept for the life of one solver.
///
/// Design note: a windowed cascade (local_cascade_solver.h) assembles a new window every round, and
/// windows overlap: the bonds near a break are assembled again in the next rounds. A bond's spring and
/// blocks depend only on the graph and the material, fixed for a solver, so they are computed once
/// (bond_spring, bond_blocks, nonzero_mask: the same calls an assembly from scratch makes, so the
/// numbers are the same bit for bit) and only for the bonds some window reached: a 10,000-bond
/// structure whose cascade stays in one corner does not pay for the rest (1.4 KB a bond).

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/material.h"
#include "algorithms/stress/rigid_body_spring/bond_spring.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace shatter {

/// What an assembly needs of one bond.
struct BondStiffness {
  BondSpring spring;
  std::array<Matrix6, 4> blocks;         ///< bond_blocks order: (y, x) = (a, a), (b, a), (a, b), (b, b)
  std::array<std::uint64_t, 4> masks{};  ///< nonzero_mask of each block
};

/// The bonds' stiffness of one graph and material (see the header note). The graph must outlive it
/// unchanged.
class BondStiffnessCache {
 public:
  BondStiffnessCache(const SupportGraph& graph, const Material& material);
  /// Computes what `bonds` need that is not kept yet. References from `at` stay valid for the cache's life.
  void prepare(std::span<const int> bonds);
  /// Bond `bond`'s stiffness; it must have been prepared.
  [[nodiscard]] const BondStiffness& at(int bond) const {
    return entries_[static_cast<std::size_t>(slot_[static_cast<std::size_t>(bond)])];
  }

 private:
  const SupportGraph* graph_;
  Material material_;
  std::vector<int> slot_;               // #bonds: index into entries_, -1 until computed
  std::vector<BondStiffness> entries_;  // in the order of first use
};

/// Computes `bond`'s stiffness into `out` (what the cache keeps).
void compute_bond_stiffness(const SupportGraph& graph, int bond, const Material& material, BondStiffness& out);

}  // namespace shatter
