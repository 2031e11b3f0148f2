#pragma once
/// One bond's spring in global axes: the translational and rotational 3 x 3 stiffness of the zero-length
/// spring at the bond centroid and the levers from its end nodes' centroids (spring_system.h has the
/// model). Shared by the per-component assembly and the whole-graph one (graph_stiffness.h), so
/// both build K from the same numbers.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/material.h"

#include <Eigen/Core>

#include <array>
#include <span>

namespace shatter {

/// Internal forces of one bond, in its frame; the forces b receives from a are minus these.
struct BondForces {
  double normal = 0.0;                ///< N, + tension
  double shear_1 = 0.0;               ///< N, along axis_1
  double shear_2 = 0.0;               ///< N, along axis_2
  double torsion = 0.0;               ///< N m, about the normal
  double moment_1 = 0.0;              ///< N m, bending about axis_1
  double moment_2 = 0.0;              ///< N m, bending about axis_2
};

/// 6 x 6 matrix of the rigid-body-spring model (translation first, then rotation).
using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// A bond's spring: relative motion delta = (u_b + theta_b x lever_b) - (u_a + theta_a x lever_a) (the
/// motions of the bond centroid with each node), phi = theta_b - theta_a; the spring force and moment b
/// receives are -translation delta and -rotation phi.
struct BondSpring {
  Eigen::Matrix3d translation;  ///< N/m, global axes: axial E A / l along the normal, shear G A / l across
  Eigen::Matrix3d rotation;     ///< N m/rad, global axes: torsion G J / l, bending E I / l
  Vec3 lever_a;                 ///< bond centroid - centroid of a, m
  Vec3 lever_b;                 ///< bond centroid - centroid of b, m
};

/// The spring of `graph.bonds[bond]` for `material`.
BondSpring bond_spring(const SupportGraph& graph, int bond, const Material& material);

/// The bond's four 6 x 6 stiffness blocks map_y^T diag(translation, rotation) map_x, indexed 2 x + y
/// with x, y in {0: a, 1: b} (block 2 x + y couples node y's equations to node x's unknowns), where
/// map_a = -[I, -[lever_a]x; 0, I] and map_b = +[I, -[lever_b]x; 0, I] take a node's unknowns to the
/// relative motion. Computed from 3 x 3 blocks, never as 6 x 6 products, so that both assemblies
/// (spring_system.cpp, graph_stiffness.cpp) use the very same numbers. Written into `out`.
void bond_blocks(const BondSpring& spring, std::span<Matrix6, 4> out);

/// The bond's internal forces from its end nodes' unknowns `u_a`, `u_b` (6 each: m, rad).
BondForces bond_forces(const Bond& bond, const BondSpring& spring, const double* u_a, const double* u_b);

}  // namespace shatter
