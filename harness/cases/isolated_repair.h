#pragma once
/// The mesh repair under a time and memory budget (docs/repair.md, "Budget").
///
/// Design note: CGAL's repair steps cost what the input's defects cost (a hole of n edges is filled in
/// O(n^3) by triangulate_hole; a soup of copies of one face intersects itself everywhere), not what
/// the mesh's size suggests, so the repair runs in a forked child with an address-space and a time
/// limit and hands back the solid in the checked form of mesh_codec.h with its report. Past a budget,
/// or on any crash of the child, the mesh is refused with one line naming the budget.

#include "algorithms/repair/repair_solid.h"

#include <cstdint>
#include <string>

namespace shatter {

/// The budget of one repair.
struct RepairBudget {
  std::uint64_t memory_bytes = 0;  ///< address space of the child, bytes; 0: kMaxRepairMemoryBytes
  double time_s = 0.0;             ///< wall time, seconds; 0: kMaxRepairSeconds (scaled in sanitized builds)
};

/// repair_solid(mesh, what) in a child under `budget`: its result, or one line starting with `what`
/// that names the budget passed or the child's end.
Result<RepairedSolid> repair_solid_isolated(const Mesh& mesh, const std::string& what, const RepairBudget& budget = {});

}  // namespace shatter
