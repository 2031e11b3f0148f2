#pragma once
/// Nodal loads and restraints of the fem-lite model: the impact, gravity, the supports, and, for a
/// model without supports, inertia relief.
///
/// Design note: a fracturing piece is usually not held (it is hit in flight or lies loose), so its
/// stiffness matrix is singular with six rigid-body modes. Inertia relief removes them the way a free
/// body does: the loads accelerate the body (a = F / m, alpha = J^-1 M about the mass centre, from the
/// lumped nodal masses), the matching d'Alembert body forces -m_i (a + alpha x r_i) are added, which
/// leaves a load with zero resultant force and moment, and six degrees of freedom are pinned in a
/// statically determinate 3-2-1 pattern (all three at the node nearest the mass centre, then the three
/// rotation-blocking components that are best conditioned). Determinate pins on a balanced load carry
/// no reaction (up to round-off), so the stresses are those of the free body. Gravity alone on a free
/// body gives no stress, as it should.

#include "algorithms/fracture/fem_lite/fem_lite_settings.h"
#include "algorithms/fracture/fem_lite/hex_grid.h"
#include "algorithms/fracture/fracturer.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace shatter {

/// Loads and restraints of one solve.
struct FemLoads {
  Eigen::VectorXd forces;                 ///< 3 #N nodal forces (x, y, z per node), N
  std::vector<std::int32_t> fixed_dofs;   ///< sorted degrees of freedom (3 node + axis) held at zero
  bool inertia_relief = false;            ///< true when some body (component) had no support and was balanced
  int loaded_nodes = 0;                   ///< nodes that carry a share of the impact
};

/// Lumped nodal masses (#N, kg) of `grid` at `density` (kg/m^3).
Eigen::VectorXd node_masses(const HexGrid& grid, double density);

/// Builds the loads of `grid`: the impact force (direction * impulse / contact_time) shared equally by
/// the nodes within the impact radius of the impact point, or applied at the nearest node when the
/// radius is 0 or holds no node; gravity on the lumped masses; the nodes inside any support box fixed.
/// Every face-connected component of the grid that no support holds is balanced by inertia relief
/// (see the note above). Error when a support box holds no node.
Result<FemLoads> fem_loads(const HexGrid& grid, const FemLiteSettings& settings, const std::optional<Impact>& impact);

}  // namespace shatter
