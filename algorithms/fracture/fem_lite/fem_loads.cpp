#include "algorithms/fracture/fem_lite/fem_loads.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <string>

namespace shatter {
namespace {

/// Index of the node nearest `p` (the lowest index on ties).
std::int32_t nearest_node(const HexGrid& grid, const Vec3& p) {
  std::int32_t best = 0;
  double best_d2 = (grid.nodes[0] - p).squaredNorm();
  for (std::size_t i = 1; i < grid.nodes.size(); ++i)
    if (const double d2 = (grid.nodes[i] - p).squaredNorm(); d2 < best_d2) {
      best_d2 = d2;
      best = static_cast<std::int32_t>(i);
    }
  return best;
}

void add_impact(const HexGrid& grid, const Impact& impact, double contact_time, FemLoads& loads) {
  const double norm = impact.direction.norm();
  if (norm == 0.0 || impact.impulse == 0.0) return;
  const Vec3 force = impact.direction / norm * (impact.impulse / contact_time);  // N
  std::vector<std::int32_t> hit;
  for (std::size_t i = 0; i < grid.nodes.size() && impact.radius > 0.0; ++i)
    if ((grid.nodes[i] - impact.point).norm() <= impact.radius) hit.push_back(static_cast<std::int32_t>(i));
  if (hit.empty()) hit.push_back(nearest_node(grid, impact.point));
  for (std::int32_t n : hit) loads.forces.segment<3>(3 * n) += force / static_cast<double>(hit.size());
  loads.loaded_nodes = static_cast<int>(hit.size());
}

/// Adds the d'Alembert forces that balance the loads on the body made of `body` (node indices) and
/// pins six of its degrees of freedom (3-2-1) into `fixed`.
void apply_inertia_relief(const HexGrid& grid, const Eigen::VectorXd& mass, const std::vector<std::int32_t>& body,
                          FemLoads& loads, std::vector<std::int32_t>& fixed) {
  double total_mass = 0.0;
  Vec3 centre = Vec3::Zero();
  for (std::int32_t i : body) {
    total_mass += mass[i];
    centre += mass[i] * grid.nodes[i];
  }
  centre /= total_mass;
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (std::int32_t i : body) {
    const Vec3 r = grid.nodes[i] - centre;
    const Vec3 f = loads.forces.segment<3>(3 * i);
    force += f;
    moment += r.cross(f);
    inertia += mass[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  const Vec3 accel = force / total_mass;
  const Vec3 alpha = inertia.ldlt().solve(moment);
  for (std::int32_t i : body) loads.forces.segment<3>(3 * i) -= mass[i] * (accel + alpha.cross(grid.nodes[i] - centre));

  // 3-2-1 pins: the node nearest the mass centre fixes the translation; the rotation omega moves
  // component k of node i by omega . (r_i x e_k), so three such rows with the largest determinant
  // (chosen greedily) fix the rotation.
  std::int32_t anchor = body.front();
  for (std::int32_t i : body)
    if ((grid.nodes[i] - centre).squaredNorm() < (grid.nodes[anchor] - centre).squaredNorm()) anchor = i;
  fixed.insert(fixed.end(), {3 * anchor, 3 * anchor + 1, 3 * anchor + 2});
  std::array<Vec3, 3> basis;  // orthonormal directions of the rows chosen so far
  for (int pick = 0; pick < 3; ++pick) {
    double best = -1.0;
    std::int32_t best_dof = -1;
    Vec3 best_row = Vec3::Zero();
    for (std::int32_t i : body) {
      const Vec3 r = grid.nodes[i] - grid.nodes[anchor];
      for (int k = 0; k < 3; ++k) {
        Vec3 row = r.cross(Vec3::Unit(k));
        for (int b = 0; b < pick; ++b) row -= row.dot(basis[b]) * basis[b];
        if (const double size = row.squaredNorm(); size > best) {
          best = size;
          best_dof = 3 * i + k;
          best_row = row;
        }
      }
    }
    basis[pick] = best_row.normalized();
    fixed.push_back(best_dof);
  }
  loads.inertia_relief = true;
}

}  // namespace

Eigen::VectorXd node_masses(const HexGrid& grid, double density) {
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(grid.nodes.size()));
  const double share = density * grid.cell_volume() / 8.0;
  for (const auto& element : grid.elements)
    for (std::int32_t node : element) mass[node] += share;
  return mass;
}

Result<FemLoads> fem_loads(const HexGrid& grid, const FemLiteSettings& settings, const std::optional<Impact>& impact) {
  FemLoads loads;
  const auto n = static_cast<Eigen::Index>(grid.nodes.size());
  loads.forces = Eigen::VectorXd::Zero(3 * n);
  if (n == 0) return loads;
  const Eigen::VectorXd mass = node_masses(grid, settings.material.density);
  if (impact) add_impact(grid, *impact, settings.contact_time, loads);
  if (settings.gravity.squaredNorm() > 0.0)
    for (Eigen::Index i = 0; i < n; ++i) loads.forces.segment<3>(3 * i) += mass[i] * settings.gravity;
  std::vector<bool> supported(static_cast<std::size_t>(grid.component_count), false);
  std::vector<std::int32_t> fixed;
  for (std::size_t s = 0; s < settings.supports.size(); ++s) {
    bool any = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!settings.supports[s].contains(grid.nodes[i])) continue;
      any = supported[grid.node_component[i]] = true;
      for (int k = 0; k < 3; ++k) fixed.push_back(static_cast<std::int32_t>(3 * i + k));
    }
    if (!any)
      return Error{"fem-lite: supports[" + std::to_string(s) + "] holds no grid node (at resolution " +
                   std::to_string(settings.resolution) + ")"};
  }
  // Every body (face-connected component) that no support holds is solved free, by inertia relief.
  std::vector<std::vector<std::int32_t>> bodies(static_cast<std::size_t>(grid.component_count));
  for (Eigen::Index i = 0; i < n; ++i) bodies[grid.node_component[i]].push_back(static_cast<std::int32_t>(i));
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (!supported[b]) apply_inertia_relief(grid, mass, bodies[b], loads, fixed);
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  loads.fixed_dofs = std::move(fixed);
  return loads;
}

}  // namespace shatter
